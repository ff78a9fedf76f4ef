import { describe, expect, it } from 'vitest';
import { exportFileName } from '../../src/classroom/export-file-name.ts';

describe('export file name', () => {
  // A local time: the pupil's clock, whatever the time zone the tests run in.
  const at = new Date(2026, 11, 6, 9, 5, 59);

  it('names the participant, the assignment and the local time, and says the time is local', () => {
    expect(exportFileName('5H2-03', 'Licht en schaduw', at, 'json')).toBe('ray-tracer-quest-5H2-03-Licht-en-schaduw-2026-12-06-09h05-local.json');
  });

  it('keeps only safe characters and leaves out what is not there', () => {
    expect(exportFileName('Zoë / ../ 07', 'Les "één", 5H2', at, 'xapi.json')).toBe('ray-tracer-quest-Zoe-07-Les-een-5H2-2026-12-06-09h05-local.xapi.json');
    expect(exportFileName(null, null, at, 'csv')).toBe('ray-tracer-quest-2026-12-06-09h05-local.csv');
    expect(exportFileName('***', '', at, 'csv')).toBe('ray-tracer-quest-2026-12-06-09h05-local.csv');
  });

  it('shortens a long title without a trailing dash', () => {
    const name = exportFileName('P1', 'Een hele lange titel voor een opdracht van de klas', at, 'json');
    expect(name).toBe('ray-tracer-quest-P1-Een-hele-lange-titel-voor-een-2026-12-06-09h05-local.json');
  });
});
