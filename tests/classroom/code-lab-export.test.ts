import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import { readExportFile } from '../../src/classroom/dashboard-read-file.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { buildExport, exportJson } from '../../src/classroom/export-json.ts';
import { exportXapi } from '../../src/classroom/export-xapi.ts';
import { summarizeCodeLabs } from '../../src/classroom/dashboard-code-labs.ts';
import { readLog, type TaskAttempt } from '../../src/classroom/task-attempts.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { newProgress } from '../../src/quest/progress.ts';

/**
 * A code lab in the classroom (issue 43: "the classroom exports record the labs"): each Run
 * tests is a `code.graded` event; the exports record per lab task its runs, the cases passed
 * at the last run, the first failing case's kind at each run, and whether it was solved.
 */

const START = '2025-03-04T09:00:00.000Z';
const LEVEL = '02-rays-from-the-camera';
const TASK = 'code-hit-sphere';
const run = (t: number, passed: number, failed: string | null): LoggedEvent => ({
  t,
  type: 'code.graded',
  level: LEVEL,
  task: TASK,
  lab: 'ray-sphere',
  passed,
  total: 306,
  failed,
});
const events: LoggedEvent[] = [
  { t: 0, type: 'session.started', at: START },
  { t: 1000, type: 'level.opened', level: LEVEL },
  { t: 1000, type: 'task.shown', level: LEVEL, task: TASK, mandatory: false, required: false, kind: 'do' },
  run(2000, 250, 'sphere-behind'),
  run(3000, 300, 'inside-sphere'),
  run(4000, 306, null),
  { t: 4000, type: 'task.completed', level: LEVEL, task: TASK, mandatory: false, required: false, how: 'done', points: 5 },
];

function input(log: LoggedEvent[]): ExportInput {
  const progress = { ...newProgress({ monotonicMs: () => 0, wallMs: () => Date.parse(START) }), log: { startedAt: START, events: log } };
  return {
    progress,
    participant: 'P1',
    installId: '11111111-2222-4333-8444-555555555555',
    attemptId: '66666666-7777-4888-9999-aaaaaaaaaaaa',
    assignment: null,
    survey: null,
    exportedAt: '2025-03-04T10:00:00.000Z',
    appVersion: '9.9.9',
    utcOffsetMin: 60,
  };
}

describe('a code lab in the exports', () => {
  it('reads the runs into the task’s attempt: the optional task starts at its first run', () => {
    const attempt = readLog({ startedAt: START, events }).attempts.find((candidate) => candidate.task === TASK);
    expect(attempt?.startedAt).toBe('2025-03-04T09:00:02.000Z');
    expect(attempt?.code).toEqual({ runs: 3, passed: 306, total: 306, failing: ['sphere-behind', 'inside-sphere', null], solved: true });
  });

  it('is not solved while no run passed every case', () => {
    const attempt = readLog({ startedAt: START, events: events.slice(0, 5) }).attempts.find((candidate) => candidate.task === TASK);
    expect(attempt?.code).toEqual({ runs: 2, passed: 300, total: 306, failing: ['sphere-behind', 'inside-sphere'], solved: false });
  });

  it('writes the code_* columns to the CSV, and the dashboard reads them back the same from a CSV and a JSON file', () => {
    const parsed = parseCsv(exportCsv(input(events)));
    if (!parsed.ok) throw new Error(parsed.error);
    const [header, ...rows] = parsed.rows;
    const row = rows.find((cells) => cells[header.indexOf('task')] === TASK) ?? [];
    const cells = ['code_runs', 'code_passed', 'code_total', 'code_failing', 'code_solved'].map((name) => row[header.indexOf(name)]);
    expect(cells).toEqual(['3', '306', '306', 'sphere-behind inside-sphere -', 'true']);
    const fromCsv = readExportFile('p1.csv', exportCsv(input(events)));
    const fromJson = readExportFile('p1.json', exportJson(input(events)));
    if (!fromCsv.ok || !fromJson.ok) throw new Error('unreadable export');
    const codeOf = (attempts: TaskAttempt[]) => attempts.find((attempt) => attempt.task === TASK)?.code;
    expect(codeOf(fromCsv.record.attempts)).toEqual({ runs: 3, passed: 306, total: 306, failing: ['sphere-behind', 'inside-sphere', null], solved: true });
    expect(codeOf(fromJson.record.attempts)).toEqual(codeOf(fromCsv.record.attempts));
  });

  it('puts the runs in the JSON export’s attempt and the xAPI statement’s extensions', () => {
    const json = buildExport(input(events));
    expect(json.attempts.find((attempt) => attempt.task === TASK)?.code?.failing).toEqual(['sphere-behind', 'inside-sphere', null]);
    const completion = exportXapi(input(events)).find(
      (statement) => statement.object.id.endsWith(`/tasks/${TASK}`) && statement.verb.id.endsWith('/completed'),
    );
    const extension = (name: string) => completion?.result?.extensions?.[`https://raytracerquest.example/extensions/${name}`];
    expect(['code-runs', 'code-passed', 'code-total', 'code-failing', 'code-solved'].map(extension)).toEqual([
      3,
      306,
      306,
      'sphere-behind inside-sphere -',
      true,
    ]);
  });
});

describe('the dashboard’s code lab table', () => {
  /** A learner who solved it after failing on sphere-behind twice, one who stopped at inside-sphere, one who never ran it. */
  const solver: LoggedEvent[] = [...events.slice(0, 3), run(2000, 250, 'sphere-behind'), run(2500, 250, 'sphere-behind'), run(3000, 306, null)];
  const stopper: LoggedEvent[] = [...events.slice(0, 3), run(2000, 300, 'inside-sphere'), run(3000, 250, 'sphere-behind')];
  const looker: LoggedEvent[] = events.slice(0, 3);

  it('counts the students who ran and who solved each lab, and the first failing kinds, most common first', () => {
    const records = [solver, stopper, looker].map((log) => {
      const read = readExportFile('p.json', exportJson(input(log)));
      if (!read.ok) throw new Error(read.reason);
      return read.record;
    });
    expect(summarizeCodeLabs(records)).toEqual([
      {
        level: LEVEL,
        task: TASK,
        learners: 2,
        solved: 1,
        failing: [
          { kind: 'sphere-behind', runs: 3 },
          { kind: 'inside-sphere', runs: 1 },
        ],
      },
    ]);
  });
});
