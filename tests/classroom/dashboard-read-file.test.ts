import { describe, expect, it } from 'vitest';
import { issueLine } from '../../src/util/issue.ts';
import { readExportFile } from '../../src/classroom/dashboard-read-file.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { CLASS_ASSIGNMENT, simulatedExport } from '../support/class-exports.ts';

const good = simulatedExport(0);
const json = (value: unknown) => JSON.stringify(value);
/** Why a file is skipped, with the schema's own line after it when there is one (as the page shows it). */
const reason = (name: string, text: string) => {
  const read = readExportFile(name, text);
  if (read.ok) return 'read';
  return read.detail === undefined ? read.reason : `${read.reason}: ${issueLine(read.detail)}`;
};

describe('reading one dropped file for the dashboard', () => {
  it('reads a JSON export: participant, assignment, attempts, visits and survey', () => {
    const read = readExportFile('p01.json', json(good));
    if (!read.ok) throw new Error(read.reason);
    expect(read.record).toMatchObject({ file: 'p01.json', participant: 'P01', assignment: CLASS_ASSIGNMENT.title });
    expect(read.record.assignmentId).toBe(good.assignment?.id);
    expect(read.record.attempts.length).toBeGreaterThan(4);
    expect(read.record.visits[0]).toMatchObject({ level: '01-introduction', passed: true });
  });

  it('reads the CSV export of the same learner to the same attempts', () => {
    const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(good.events.startedAt) };
    const csv = exportCsv({
      progress: { ...newProgress(clock), log: good.events },
      participant: good.participant,
      installId: good.learner.installId,
      attemptId: good.learner.attemptId,
      assignment: CLASS_ASSIGNMENT,
      survey: null,
      exportedAt: good.exportedAt,
      appVersion: '0.1.0',
    });
    const fromCsv = readExportFile('p01.csv', csv);
    const fromJson = readExportFile('p01.json', json(good));
    if (!fromCsv.ok || !fromJson.ok) throw new Error('both should read');
    expect(fromCsv.record.attempts).toEqual(fromJson.record.attempts);
    expect(fromCsv.record).toMatchObject({
      participant: 'P01',
      assignment: CLASS_ASSIGNMENT.title,
      assignmentId: fromJson.record.assignmentId,
      visits: [],
      survey: null,
    });
    expect(fromCsv.record).toMatchObject({ learnerId: 'P01', attemptId: good.learner.attemptId, installId: good.learner.installId, classCode: '' });
    expect(fromJson.record).toMatchObject({ learnerId: 'P01', attemptId: good.learner.attemptId, installId: good.learner.installId });
  });

  it('reads a code typed in lower case as the same learner as in capitals', () => {
    const lower = readExportFile('p01-lower.json', json({ ...good, participant: 'p01', learner: { ...good.learner, id: 'p01' } }));
    const upper = readExportFile('p01.json', json(good));
    if (!lower.ok || !upper.ok) throw new Error('both should read');
    expect(lower.record).toMatchObject({ participant: 'P01', learnerId: 'P01' });
    expect(lower.record.learnerId).toBe(upper.record.learnerId);
  });

  it('reads a CSV export from before hint offers: no offers, its hints as opened', () => {
    const header = 'participant,level,task,started_at,completed_at,duration_ms,active_ms,how,hints_text,hints_guidance';
    const read = readExportFile('old.csv', `${header}\r\nP1,01-introduction,orbit,2026-03-09T09:00:00.000Z,2026-03-09T09:00:05.000Z,5000,5000,done,1,0\r\n`);
    if (!read.ok) throw new Error(read.reason);
    expect(read.record.attempts).toMatchObject([{ task: 'orbit', hintsText: 1, hintsGuidance: 0, hintsOffered: 0 }]);
  });

  it('names why a file is skipped', () => {
    expect(reason('a.json', '')).toBe('the file is empty');
    expect(reason('a.json', json(good).slice(0, 200))).toMatch(/^the file is damaged: \(root\): not valid JSON at line \d+, column \d+/);
    expect(reason('photo.png', '\u0089PNG\r\n\u001a\n\u0000\u0000')).toMatch(/not a text file/);
    expect(reason('notes.txt', 'hello there')).toMatch(/not a Ray Tracer Quest export/);
    expect(reason('list.json', '[1, 2]')).toMatch(/holds no JSON object/);
    expect(reason('p.xapi.json', json([{ actor: { objectType: 'Agent' }, verb: { id: 'x' }, object: {} }]))).toMatch(
      /^xAPI statements, which are for a school's learning record store/,
    );
    expect(reason('scene.json', json({ version: 1, objects: [] }))).toMatch(/no "format": "ray-tracer-quest-export"/);
    expect(reason('progress.json', json({ kind: 'ray-tracer-quest-progress', version: 1 }))).toMatch(/a saved progress file, not an export/);
    expect(reason('future.json', json({ ...good, version: 2 }))).toMatch(/newer version of the app \(export version 2\)/);
    expect(reason('p.json', json({ ...good, participant: 42 }))).toBe('damaged export: participant: must be a string, got 42');
  });

  it('points at the damaged event in a log', () => {
    const events = good.events.events.map((event, index) => (index === 3 ? { ...event, t: -5 } : event));
    expect(reason('p.json', json({ ...good, events: { ...good.events, events } }))).toBe('damaged event log: events.events[3].t: must be at least 0, got -5');
    const backwards = good.events.events.map((event, index) => (index === 4 ? { ...event, t: 0 } : event));
    expect(reason('p.json', json({ ...good, events: { ...good.events, events: backwards } }))).toBe(
      'damaged event log: events.events[4].t: must not be earlier than the event before it',
    );
  });

  it('names the damage in a CSV export', () => {
    expect(reason('a.csv', 'participant,level\nP1,L1\n')).toBe(
      'not a Ray Tracer Quest CSV export (no column "task", "started_at", "duration_ms", "active_ms")',
    );
    const header = 'participant,level,task,started_at,duration_ms,active_ms\n';
    expect(reason('a.csv', `${header}P1,L1,a,2026-03-09T09:00:00Z,ten,5\n`)).toBe('damaged CSV: line 2: duration_ms must be a number of at least 0, got "ten"');
    expect(reason('a.csv', `${header}P1,L1,a,yesterday,10,5\n`)).toBe('damaged CSV: line 2: started_at is not a date');
    expect(reason('a.csv', `${header}"P1,L1,a,2026-03-09T09:00:00Z,10,5\n`)).toBe('damaged CSV: a quoted field that starts on line 2 is never closed');
  });
});
