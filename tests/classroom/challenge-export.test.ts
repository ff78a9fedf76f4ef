import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import { reachedMatch, summarizeChallenges } from '../../src/classroom/dashboard-challenges.ts';
import { readExportFile } from '../../src/classroom/dashboard-read-file.ts';
import type { ClassRecord } from '../../src/classroom/dashboard-record.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { buildExport, exportJson } from '../../src/classroom/export-json.ts';
import { exportXapi } from '../../src/classroom/export-xapi.ts';
import { readLog } from '../../src/classroom/task-attempts.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { newProgress } from '../../src/quest/progress.ts';

/**
 * A challenge in the classroom (spec/challenges.md §3): the exports record, per challenge
 * attempt, its renders, changes, rays, the match score at each render and the stars; the
 * dashboard works out from the learners' raw events how close the class got and where each
 * learner who did not match stopped.
 */

const START = '2025-03-04T09:00:00.000Z';
const LEVEL = '25-match-the-highlight';
const flags = { mandatory: true, required: true };
const shown = (t: number): LoggedEvent => ({ t, type: 'task.shown', level: LEVEL, task: 'match', ...flags, kind: 'do' });
const compared = (t: number, score: number, renders: number, changes: number, rays: number): LoggedEvent => ({
  t,
  type: 'challenge.compared',
  level: LEVEL,
  task: 'match',
  difference: 0.0001 * 10 ** ((75 - score) / 25),
  renders,
  changes,
  rays,
  score,
});
const completed = (t: number, how: 'done' | 'shown', points: number, stars?: 1 | 2 | 3): LoggedEvent => ({
  t,
  type: 'task.completed',
  level: LEVEL,
  task: 'match',
  ...flags,
  how,
  points,
  ...(stars === undefined ? {} : { stars }),
});
const opened = (t: number): LoggedEvent => ({ t, type: 'level.opened', level: LEVEL });
const closed = (t: number): LoggedEvent => ({ t, type: 'level.closed', level: LEVEL });

/** Matched on the third render, after four changes: two stars. */
const matcher: LoggedEvent[] = [
  { t: 0, type: 'session.started', at: START },
  opened(1000),
  shown(1000),
  compared(2000, 25, 1, 1, 1000),
  compared(3000, 60, 2, 3, 2000),
  compared(4000, 80, 3, 4, 3000),
  completed(4000, 'done', 7, 2),
];
/** Left at 40, came back, stopped at 55. */
const stopper: LoggedEvent[] = [
  { t: 0, type: 'session.started', at: START },
  opened(1000),
  shown(1000),
  compared(2000, 10, 1, 1, 500),
  compared(3000, 40, 2, 2, 1000),
  closed(5000),
  opened(6000),
  shown(6000),
  compared(7000, 55, 1, 1, 500),
];
/** Got to 30, then "Show me" matched it (90): no stars, and not a learner who stopped. */
const shownTo: LoggedEvent[] = [
  { t: 0, type: 'session.started', at: START },
  opened(1000),
  shown(1000),
  compared(2000, 30, 1, 1, 500),
  compared(3000, 90, 2, 2, 1000),
  completed(3000, 'shown', 0),
];
/** Saw the task, never rendered. */
const looker: LoggedEvent[] = [{ t: 0, type: 'session.started', at: START }, opened(1000), shown(1000)];

function input(events: LoggedEvent[], participant: string): ExportInput {
  const progress = { ...newProgress({ monotonicMs: () => 0, wallMs: () => Date.parse(START) }), log: { startedAt: START, events } };
  return {
    progress,
    participant,
    installId: `11111111-2222-4333-8444-55555555555${participant.length}`,
    attemptId: `66666666-7777-4888-9999-${participant.padStart(12, 'a')}`,
    assignment: null,
    survey: null,
    exportedAt: '2025-03-04T10:00:00.000Z',
    appVersion: '9.9.9',
    utcOffsetMin: 60,
  };
}

describe('a challenge in the exports', () => {
  it('is read from the log as renders, changes, rays, the score of each render and the stars', () => {
    expect(readLog({ startedAt: START, events: matcher }).attempts.map((attempt) => attempt.challenge)).toEqual([
      { renders: 3, changes: 4, rays: 3000, scores: [25, 60, 80], stars: 2 },
    ]);
    // Each attempt counts its own renders; the stars are only for a match by the learner.
    expect(readLog({ startedAt: START, events: stopper }).attempts.map((attempt) => attempt.challenge)).toEqual([
      { renders: 2, changes: 2, rays: 1000, scores: [10, 40], stars: null },
      { renders: 1, changes: 1, rays: 500, scores: [55], stars: null },
    ]);
    expect(readLog({ startedAt: START, events: looker }).attempts[0].challenge).toBeUndefined();
  });

  it('fills the CSV’s challenge columns, and leaves them empty for a task that is not one', () => {
    const parsed = parseCsv(exportCsv(input([...matcher, { t: 5000, type: 'task.shown', level: LEVEL, task: 'other', ...flags }], 'P1')));
    if (!parsed.ok) throw new Error(parsed.error);
    const [header, ...rows] = parsed.rows;
    const cells = (row: string[]) =>
      ['challenge_renders', 'challenge_changes', 'challenge_rays', 'challenge_scores', 'challenge_stars'].map((name) => row[header.indexOf(name)]);
    expect(rows.map(cells)).toEqual([
      ['3', '4', '3000', '25 60 80', '2'],
      ['', '', '', '', ''],
    ]);
  });

  it('puts the same in the JSON’s attempts and the xAPI completion', () => {
    expect(buildExport(input(matcher, 'P1')).attempts[0].challenge).toEqual({ renders: 3, changes: 4, rays: 3000, scores: [25, 60, 80], stars: 2 });
    const completion = exportXapi(input(matcher, 'P1')).find(
      (statement) => statement.object.id.endsWith('/tasks/match') && statement.verb.id.endsWith('/completed'),
    );
    const extension = (name: string) => completion?.result?.extensions?.[`https://raytracerquest.example/extensions/${name}`];
    expect(['challenge-renders', 'challenge-changes', 'challenge-rays', 'challenge-scores', 'challenge-stars'].map(extension)).toEqual([
      3,
      4,
      3000,
      '25 60 80',
      2,
    ]);
  });

  it('is read back by the dashboard the same from a CSV and from a JSON file', () => {
    const fromCsv = readExportFile('p1.csv', exportCsv(input(matcher, 'P1')));
    const fromJson = readExportFile('p1.json', exportJson(input(matcher, 'P1')));
    if (!fromCsv.ok || !fromJson.ok) throw new Error('unreadable export');
    expect(fromCsv.record.attempts[0].challenge).toEqual(fromJson.record.attempts[0].challenge);
  });
});

describe('the dashboard’s challenge figures', () => {
  const records = (): ClassRecord[] =>
    [
      [matcher, 'P1'],
      [stopper, 'P2'],
      [shownTo, 'P3'],
      [looker, 'P4'],
    ].map(([events, participant]) => {
      const read = readExportFile(`${participant as string}.json`, exportJson(input(events as LoggedEvent[], participant as string)));
      if (!read.ok) throw new Error(read.reason);
      return read.record;
    });

  it('show how close each learner got at best, who matched with how many stars, and where the others stopped', () => {
    const [summary, ...others] = summarizeChallenges(records());
    expect(others).toEqual([]);
    expect(summary).toEqual({
      level: LEVEL,
      task: 'match',
      // The looker never rendered: not counted.
      learners: 3,
      bestScores: [55, 80, 90],
      matched: 1,
      stars: [0, 1, 0],
      // Only the stopper: its last render, in its second visit.
      stoppedAt: [55],
    });
    // 80 (matched) and 90 (shown) reach a match score of 75.
    expect(reachedMatch(summary)).toBe(2);
  });

  it('are worked out again from the raw events: a log with one more render of the stopper moves it', () => {
    const all = records();
    const stopperLog = [...stopper, compared(8000, 70, 2, 2, 1000)];
    const read = readExportFile('P2.json', exportJson(input(stopperLog, 'P2')));
    if (!read.ok) throw new Error(read.reason);
    const [summary] = summarizeChallenges([all[0], read.record, all[2], all[3]]);
    expect(summary.bestScores).toEqual([70, 80, 90]);
    expect(summary.stoppedAt).toEqual([70]);
  });
});
