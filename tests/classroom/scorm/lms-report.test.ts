import { readFileSync } from 'node:fs';
import { Scorm12API, Scorm2004API } from 'scorm-again';
import { describe, expect, it } from 'vitest';
import { exitValues, interactionValues, statusValues, timespan12 } from '../../../src/classroom/scorm/cmi-values.ts';
import { findLmsApi } from '../../../src/classroom/scorm/lms-api.ts';
import { lmsReport } from '../../../src/classroom/scorm/lms-report.ts';
import { resumeProgress, suspendProgress, SUSPEND_DATA_LIMIT } from '../../../src/classroom/scorm/suspend-data.ts';
import type { LoggedEvent } from '../../../src/quest/event-log.ts';
import { parseLevelJson, type Level } from '../../../src/quest/level-schema.ts';
import { newProgress, type Progress } from '../../../src/quest/progress.ts';

const START = '2026-03-04T09:00:00.000Z';
const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(START) };

function readLevel(id: string): Level {
  const parsed = parseLevelJson(readFileSync(new URL(`../../../levels/${id}.level.json`, import.meta.url), 'utf8'));
  if (!parsed.ok) throw new Error(parsed.errors.join('\n'));
  return parsed.level;
}

const L1 = '01-introduction';
const L2 = '02-rays-from-the-camera';
const levels = [readLevel(L1), readLevel(L2)];
const requiredTasks = { [L1]: ['orbit', 'zoom'], [L2]: ['predict-light-path'] };
const req = { mandatory: true, required: true };
const opt = { mandatory: false, required: false };

/**
 * Level 1: orbit done after 4 s, zoom by "show me"; the optional "pan" shown and never
 * touched; "turn the box" touched and skipped. Level 2: the info step read, the prediction
 * answered wrong (choice 3) and then right, an estimate answered.
 */
const events: LoggedEvent[] = [
  { t: 0, type: 'session.started', at: START },
  { t: 1_000, type: 'level.opened', level: L1 },
  { t: 1_000, type: 'task.shown', level: L1, task: 'orbit', ...req, kind: 'do' },
  { t: 1_000, type: 'task.shown', level: L1, task: 'pan', ...opt, kind: 'do' },
  { t: 1_000, type: 'task.shown', level: L1, task: 'turn-box', ...opt, kind: 'do' },
  { t: 5_000, type: 'task.completed', level: L1, task: 'orbit', ...req, how: 'done', points: 10 },
  { t: 5_000, type: 'task.shown', level: L1, task: 'zoom', ...req, kind: 'do' },
  { t: 6_000, type: 'task.started', level: L1, task: 'turn-box' },
  { t: 9_000, type: 'task.completed', level: L1, task: 'zoom', ...req, how: 'shown', points: 0 },
  { t: 9_500, type: 'task.completed', level: L1, task: 'turn-box', ...opt, how: 'skipped', points: 0 },
  { t: 9_500, type: 'level.passed', level: L1 },
  { t: 10_000, type: 'level.closed', level: L1 },
  { t: 11_000, type: 'level.opened', level: L2 },
  { t: 11_000, type: 'task.shown', level: L2, task: 'the-screen', ...opt, kind: 'info' },
  { t: 11_000, type: 'task.shown', level: L2, task: 'predict-light-path', ...req, kind: 'quiz' },
  { t: 11_000, type: 'task.shown', level: L2, task: 'predict-render-rays', ...opt, kind: 'quiz' },
  { t: 12_000, type: 'task.completed', level: L2, task: 'the-screen', ...opt, how: 'done', points: 0 },
  { t: 14_500, type: 'quiz.answered', level: L2, task: 'predict-light-path', choice: 3, correct: false },
  { t: 14_500, type: 'task.completed', level: L2, task: 'predict-light-path', ...req, how: 'done', points: 0 },
  { t: 16_000, type: 'task.started', level: L2, task: 'predict-render-rays' },
  { t: 20_000, type: 'quiz.answered', level: L2, task: 'predict-render-rays', value: 307200, correct: true },
];

function progressOf(log: LoggedEvent[], tasks: Progress['levels']): Progress {
  return { ...newProgress(clock), levels: tasks, log: { startedAt: START, events: log } };
}

const played = progressOf(events, {
  [L1]: { tasks: { orbit: { how: 'done', points: 10 }, zoom: { how: 'shown', points: 0 }, 'turn-box': { how: 'skipped', points: 0 } }, hintsUsed: 1 },
  [L2]: { tasks: { 'the-screen': { how: 'done', points: 0 }, 'predict-light-path': { how: 'done', points: 0, correct: false } }, hintsUsed: 0 },
});

describe('what the game reports to a learning platform', () => {
  const report = lmsReport(played, { levels, requiredTasks });

  it('scores the required tasks only, and is complete when every level is passed', () => {
    expect(report.score).toEqual({ raw: 10, max: 30 });
    expect(report.completed).toBe(true);
    const halfway = lmsReport(progressOf(events.slice(0, 8), { [L1]: played.levels[L1] }), { levels, requiredTasks });
    expect(halfway.completed).toBe(false);
    // Without the teacher's choice, the levels' mandatory tasks count.
    expect(lmsReport(played, { levels, requiredTasks: undefined }).score.max).toBe(
      levels.flatMap((level) => level.tasks.filter((task) => task.mandatory)).reduce((sum, task) => sum + task.points, 0),
    );
  });

  it('has one interaction per task and quiz the learner did: none for untouched tasks or information steps', () => {
    expect(report.interactions.map(({ id, type, response, result }) => [id, type, response, result])).toEqual([
      [`${L1}/orbit`, 'other', 'done', 'correct'],
      [`${L1}/zoom`, 'other', 'shown', 'neutral'],
      [`${L1}/turn-box`, 'other', 'skipped', 'neutral'],
      [`${L2}/predict-light-path`, 'choice', 'd', 'incorrect'],
      [`${L2}/predict-render-rays`, 'numeric', '307200', 'correct'],
    ]);
  });

  it('times each from when the task began: shown for a required one, first touched for an optional one', () => {
    const byId = new Map(report.interactions.map((interaction) => [interaction.id, interaction]));
    expect(byId.get(`${L1}/orbit`)).toMatchObject({ timestamp: '2026-03-04T09:00:01.000Z', latencyMs: 4_000 });
    expect(byId.get(`${L1}/turn-box`)).toMatchObject({ timestamp: '2026-03-04T09:00:06.000Z', latencyMs: 3_500 });
    expect(byId.get(`${L2}/predict-light-path`)).toMatchObject({ latencyMs: 3_500 });
    expect(byId.get(`${L2}/predict-render-rays`)).toMatchObject({ latencyMs: 4_000 });
  });

  it('keeps a quiz’s first answer: a later right one does not change it', () => {
    const retried = progressOf(
      [...events, { t: 21_000, type: 'quiz.answered', level: L2, task: 'predict-light-path', choice: 1, correct: true }],
      played.levels,
    );
    expect(lmsReport(retried, { levels, requiredTasks }).interactions).toEqual(report.interactions);
  });
});

describe('the report in each SCORM version’s data model', () => {
  const report = lmsReport(played, { levels, requiredTasks });
  const quiz = report.interactions[3];

  it('SCORM 2004: completion and success, a scaled score, ISO 8601 times', () => {
    expect(Object.fromEntries(statusValues('2004', report, L2))).toEqual({
      'cmi.completion_status': 'completed',
      'cmi.success_status': 'passed',
      'cmi.score.min': '0',
      'cmi.score.max': '30',
      'cmi.score.raw': '10',
      'cmi.score.scaled': '0.3333',
      'cmi.location': L2,
    });
    expect(Object.fromEntries(interactionValues('2004', 4, quiz))).toEqual({
      'cmi.interactions.4.id': `${L2}/predict-light-path`,
      'cmi.interactions.4.type': 'choice',
      'cmi.interactions.4.timestamp': '2026-03-04T09:00:11.00Z',
      'cmi.interactions.4.learner_response': 'd',
      'cmi.interactions.4.result': 'incorrect',
      'cmi.interactions.4.latency': 'PT3.5S',
    });
  });

  it('SCORM 1.2: a lesson status, a score in 0–100, a letter for a choice, wrong for incorrect', () => {
    const unfinished = { ...report, completed: false };
    expect(Object.fromEntries(statusValues('1.2', unfinished, null))).toEqual({
      'cmi.core.lesson_status': 'incomplete',
      'cmi.core.score.min': '0',
      'cmi.core.score.max': '100',
      'cmi.core.score.raw': '33.33',
    });
    expect(Object.fromEntries(interactionValues('1.2', 0, quiz))).toEqual({
      'cmi.interactions.0.id': `${L2}/predict-light-path`,
      'cmi.interactions.0.type': 'choice',
      'cmi.interactions.0.time': '09:00:11',
      'cmi.interactions.0.student_response': 'd',
      'cmi.interactions.0.result': 'wrong',
      'cmi.interactions.0.latency': '0000:00:03.50',
    });
    expect(interactionValues('1.2', 0, report.interactions[0])[1]).toEqual(['cmi.interactions.0.type', 'performance']);
    expect(timespan12(3_723_456)).toBe('0001:02:03.46');
  });
});

describe('the progress in the platform’s suspend data', () => {
  it('comes back as it was, without the scenes', () => {
    const { text, part } = suspendProgress(played, SUSPEND_DATA_LIMIT['1.2']);
    expect(part).toBe('full');
    expect(text.length).toBeLessThanOrEqual(4096);
    const back = resumeProgress(text, START)!;
    expect(back.levels).toEqual(played.levels);
    expect(back.log).toEqual(played.log);
    expect([back.sandbox, back.current]).toEqual([null, null]);
  });

  it('keeps only the completed tasks when the log does not fit, and nothing when they do not either', () => {
    // A long lesson: hundreds of hints and renders, 1.2's 4096 characters are not enough for the log.
    const busy = Array.from({ length: 3000 }, (_, n): LoggedEvent => ({
      t: 30_000 + n * 997,
      id: `s${n % 97}.${n}`,
      type: 'render.finished',
      level: L2,
      ms: (n * 7919) % 100_000,
    }));
    const long = progressOf([...events, ...busy], played.levels);
    const tasksOnly = suspendProgress(long, SUSPEND_DATA_LIMIT['1.2']);
    expect(tasksOnly.part).toBe('tasks');
    const back = resumeProgress(tasksOnly.text, '2026-03-05T10:00:00.000Z')!;
    expect(back.levels).toEqual(played.levels);
    expect(back.log).toEqual({ startedAt: '2026-03-05T10:00:00.000Z', events: [] });
    expect(suspendProgress(long, SUSPEND_DATA_LIMIT['2004']).part).toBe('full');
    expect(suspendProgress(played, 20)).toEqual({ text: '', part: 'none' });
  });

  it('is refused when it is not ours or damaged', () => {
    expect(resumeProgress('', START)).toBeNull();
    expect(resumeProgress('viewed=1,2,3|slide=4', START)).toBeNull();
    const { text } = suspendProgress(played, 64000);
    expect(resumeProgress(text.slice(0, -12), START)).toBeNull();
  });
});

describe('the values as scorm-again (an independent SCORM runtime) takes them', () => {
  const report = lmsReport(played, { levels, requiredTasks });
  const { text } = suspendProgress(played, SUSPEND_DATA_LIMIT['1.2']);

  it.each(['1.2', '2004'] as const)('SCORM %s: every value is accepted and kept', (version) => {
    const runtime = version === '2004' ? new Scorm2004API({ logLevel: 5 }) : new Scorm12API({ logLevel: 5 });
    const lms = findLmsApi({ parent: { parent: null, ...(version === '2004' ? { API_1484_11: runtime } : { API: runtime }) } })!;
    expect(lms.initialize()).toBe(true);
    const values = [
      ...statusValues(version, report, L2),
      ...report.interactions.flatMap((interaction, n) => interactionValues(version, n, interaction)),
      ...exitValues(version, 754_321),
      ['cmi.suspend_data', text] as const,
    ];
    const refused = values.filter(([element, value]) => !lms.set(element, value)).map(([element, value]) => `${element}=${value}: ${lms.lastError()}`);
    expect(refused).toEqual([]);
    expect(lms.commit()).toBe(true);
    const kept = runtime.getFlattenedCMI() as Record<string, string>;
    // The session time goes into the total and the exit is not read back; 1.2's latencies are kept in a shorter form (00:00:04).
    const readable = values.filter(([element]) => !/session_time|\.exit$/.test(element) && !(version === '1.2' && element.endsWith('.latency')));
    expect(Object.fromEntries(readable.map(([element]) => [element, kept[element]]))).toEqual(Object.fromEntries(readable));
  });
});
