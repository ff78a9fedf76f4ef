import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { assignmentId } from '../../src/classroom/assignment-id.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { APP_VERSION } from '../../src/classroom/export-context.ts';
import { ATTEMPT_COLUMNS } from '../../src/classroom/attempt-columns.ts';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import { buildExport, EXPORT_FORMAT } from '../../src/classroom/export-json.ts';
import { exportXapi } from '../../src/classroom/export-xapi.ts';
import { isoAt, isoDuration } from '../../src/classroom/iso-duration.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { newProgress, type Progress } from '../../src/quest/progress.ts';

const CSV_COLUMNS = ATTEMPT_COLUMNS.map((column) => column.name);
const START = '2025-03-04T09:00:00.000Z';
const clock = { monotonicMs: () => 0, wallMs: () => Date.parse(START) };
const flags = { mandatory: true, required: true };
const INSTALL = '11111111-2222-4333-8444-555555555555';
const ATTEMPT = '66666666-7777-4888-9999-aaaaaaaaaaaa';

/**
 * A learner opens level 1, asks for a hint and hides the tab for 20 s while on "orbit",
 * finishes it; "select" is shown, its ring comes by itself after idle time (a log from before
 * hint offers), they leave the level, come back (a second attempt), open the hint offered
 * after idle time and finish it by "show me"; an optional task is skipped (touched only the
 * second time); a quiz is offered a hint that is not opened, and answered wrong; an
 * optional info step is never read.
 */
const events: LoggedEvent[] = [
  { t: 0, type: 'session.started', at: START },
  { t: 1_000, type: 'level.opened', level: 'l1' },
  { t: 1_000, type: 'task.shown', level: 'l1', task: 'orbit', ...flags },
  { t: 1_000, type: 'task.shown', level: 'l1', task: 'extra', mandatory: false, required: false },
  { t: 1_000, type: 'task.shown', level: 'l1', task: 'about', mandatory: true, required: false, kind: 'info' },
  { t: 5_000, type: 'hint.shown', level: 'l1', task: 'orbit', step: 'text', trigger: 'asked' },
  { t: 6_000, type: 'tab.hidden' },
  { t: 26_000, type: 'tab.visible' },
  { t: 31_000, type: 'task.completed', level: 'l1', task: 'orbit', ...flags, how: 'done', points: 10 },
  { t: 31_000, type: 'task.shown', level: 'l1', task: 'select', ...flags },
  { t: 32_000, type: 'hint.shown', level: 'l1', task: 'select', step: 'guidance', trigger: 'idle' },
  { t: 40_000, type: 'level.closed', level: 'l1' },
  { t: 50_000, type: 'level.opened', level: 'l1' },
  { t: 50_000, type: 'task.shown', level: 'l1', task: 'select', ...flags },
  { t: 50_000, type: 'task.shown', level: 'l1', task: 'extra', mandatory: false, required: false },
  { t: 51_000, type: 'task.started', level: 'l1', task: 'extra' },
  { t: 51_200, type: 'hint.offered', level: 'l1', task: 'select', step: 'text' },
  { t: 51_800, type: 'hint.shown', level: 'l1', task: 'select', step: 'text', trigger: 'offered' },
  { t: 52_000, type: 'explanation.expanded', level: 'l1', task: 'select' },
  { t: 53_500, type: 'task.completed', level: 'l1', task: 'select', ...flags, how: 'shown', points: 0 },
  { t: 54_000, type: 'task.completed', level: 'l1', task: 'extra', mandatory: false, required: false, how: 'skipped', points: 0 },
  { t: 54_000, type: 'level.passed', level: 'l1' },
  { t: 54_000, type: 'badge.earned', badge: { kind: 'first-render' } },
  { t: 60_000, type: 'task.shown', level: 'l1', task: 'guess', ...flags, kind: 'quiz' },
  { t: 60_500, type: 'task.shown', level: 'l1', task: 'read', ...flags, kind: 'info' },
  { t: 60_700, type: 'hint.offered', level: 'l1', task: 'guess', step: 'text' },
  { t: 61_000, type: 'quiz.answered', level: 'l1', task: 'guess', choice: 2, correct: false },
  { t: 61_000, type: 'task.completed', level: 'l1', task: 'guess', ...flags, how: 'done', points: 5 },
  { t: 62_000, type: 'render.started', level: 'l1' },
];

function progress(): Progress {
  const fresh = newProgress(clock);
  return { ...fresh, log: { startedAt: START, events }, levels: { l1: { tasks: { orbit: { how: 'done', points: 10 } }, hintsUsed: 2 } } };
}

const assignment: Assignment = {
  version: 1,
  title: 'Lesson, "one", line\nbreak',
  levels: ['l1'],
  requiredTasks: {},
  otherLevels: 'shown',
  locale: 'nl',
  askParticipantCode: true,
  survey: 'default',
};

function input(overrides: Partial<ExportInput> = {}): ExportInput {
  return {
    progress: progress(),
    participant: 'P-07, ü',
    installId: INSTALL,
    attemptId: ATTEMPT,
    assignment,
    survey: { survey: 'default', submittedAt: '2025-03-04T10:00:00.000Z', answers: { 'computer-skill': 7, feedback: 'Nice, "really"' } },
    exportedAt: '2025-03-04T10:01:00.000Z',
    appVersion: '9.9.9',
    utcOffsetMin: -330,
    optionText: (level, task, position) => `${level}/${task} option ${position}`,
    ...overrides,
  };
}

function csvRows(text: string): Record<string, string>[] {
  const parsed = parseCsv(text);
  if (!parsed.ok) throw new Error(parsed.error);
  const [header, ...rows] = parsed.rows;
  return rows.map((row) => Object.fromEntries(header.map((name, i) => [name, row[i]])));
}

describe('CSV export', () => {
  const text = exportCsv(input());
  // Level l1 teaches none of the ideas some questions ask about: those are not asked, and have no column.
  const questions = surveyById('default')!
    .questions.filter((question) => !question.levels)
    .map((question) => `survey_${question.id}`);

  it('starts with a byte-order mark and the header, with CRLF line ends', () => {
    expect(text.startsWith(`\uFEFF${[...CSV_COLUMNS, ...questions].join(',')}\r\n`)).toBe(true);
    expect(text.endsWith('\r\n')).toBe(true);
    for (const column of [
      'participant',
      'assignment',
      'level',
      'task',
      'mandatory',
      'started_at',
      'completed_at',
      'duration_ms',
      'active_ms',
      'hints_text',
      'hints_guidance',
      'shown_by_app',
      'attempts',
      'points',
    ]) {
      expect(CSV_COLUMNS).toContain(column);
    }
  });

  it('quotes fields with commas, quotes and line breaks (RFC 4180)', () => {
    expect(text).toContain('"P-07, ü","Lesson, ""one"", line\nbreak"');
    // Identifiers are always quoted, so readers told to keep quoted fields as text keep them.
    expect(text).toContain(`"P-07, ü","${ATTEMPT}","${INSTALL}","P-07, ü"`);
    const [first] = csvRows(text);
    expect(first.participant).toBe('P-07, ü');
    expect(first.assignment).toBe('Lesson, "one", line\nbreak');
    expect(first.assignment_id).toBe(assignmentId(assignment));
  });

  it('has one row per task attempt with times, hints and how it ended', () => {
    const rows = csvRows(text);
    // The optional task is timed only from its first move, in the second visit; the optional info step never.
    expect(rows.map((row) => `${row.task}#${row.attempts}:${row.how}`)).toEqual([
      'orbit#1:done',
      'select#1:',
      'select#2:shown',
      'extra#1:skipped',
      'guess#1:done',
      'read#1:',
    ]);
    const [orbit, select1, select2, extra, guess, read] = rows;
    expect(orbit).toMatchObject({
      mandatory: 'true',
      started_at: '2025-03-04T09:00:01.000Z',
      completed_at: '2025-03-04T09:00:31.000Z',
      duration_ms: '30000',
      hints_text: '1',
      hints_guidance: '0',
      shown_by_app: 'false',
      points: '10',
    });
    // Unfinished: the level was closed. Its ring came by itself (an older log): offered, not opened.
    expect(select1).toMatchObject({ completed_at: '', duration_ms: '9000', hints_guidance: '0', hints_offered: '1', hints_opened: '0' });
    expect(select2).toMatchObject({ shown_by_app: 'true', duration_ms: '3500', points: '0', quiz_correct: '' });
    expect(extra).toMatchObject({ mandatory: 'false', started_at: '2025-03-04T09:00:51.000Z', duration_ms: '3000' });
    expect(guess).toMatchObject({ kind: 'quiz', quiz_answers: '1', quiz_correct: 'false', points: '5' });
    // The third choice in the level file, by its letter and its text in the export's language.
    expect(guess).toMatchObject({ quiz_choice: 'c', quiz_choice_text: 'l1/guess option 2' });
    expect(rows.filter((row) => row.quiz_choice !== '').map((row) => row.task)).toEqual(['guess']);
    expect(rows.map((row) => `${row.task}#${row.attempts}:${row.explanation_opens}`)).toEqual([
      'orbit#1:0',
      'select#1:0',
      'select#2:1',
      'extra#1:0',
      'guess#1:0',
      'read#1:0',
    ]);
    for (const row of rows) expect(row).toMatchObject({ app_version: '9.9.9', utc_offset_min: '-330' });
    // Hints asked for and offered ones opened count as opened; an offer left alone only as offered.
    expect(rows.map((row) => `${row.task}#${row.attempts}:${row.hints_offered}/${row.hints_opened}`)).toEqual([
      'orbit#1:0/1',
      'select#1:1/0',
      'select#2:1/1',
      'extra#1:0/0',
      'guess#1:1/0',
      'read#1:0/0',
    ]);
    // An info step is read, not done: never mandatory, even when it is required.
    expect(read).toMatchObject({ kind: 'info', mandatory: 'false' });
  });

  it('names the learner and the playthrough in every row', () => {
    for (const row of csvRows(text)) {
      expect(row).toMatchObject({ learner_id: 'P-07, ü', attempt_id: ATTEMPT, install_id: INSTALL, class_code: '' });
    }
    const [anonymous] = csvRows(exportCsv(input({ participant: null, assignment: { ...assignment, classCode: '3B' } })));
    expect(anonymous).toMatchObject({ learner_id: `install:${INSTALL}`, participant: '', class_code: '3B' });
  });

  it('puts the survey answers in one column per question, on each row', () => {
    const rows = csvRows(text);
    expect(Object.keys(rows[0]).filter((column) => column.startsWith('survey_'))).toEqual(questions);
    for (const row of rows)
      expect(row).toMatchObject({ survey: 'default', 'survey_computer-skill': '7', survey_feedback: 'Nice, "really"', survey_education: '' });
    // Not answered yet: the assignment's survey columns are there, empty.
    const [before] = csvRows(exportCsv(input({ survey: null })));
    expect(before).toMatchObject({ survey: '', 'survey_computer-skill': '' });
    // The teacher's own choice: a question ticked off has no column, one ticked on has one.
    const chosen = csvRows(exportCsv(input({ assignment: { ...assignment, surveyQuestions: { age: false, 'learned-soft-shadows': true } } })));
    const columns = Object.keys(chosen[0]);
    expect(columns).not.toContain('survey_age');
    expect(columns).toContain('survey_learned-soft-shadows');
    expect(columns).not.toContain('survey_learned-attenuation');
    // Free play without a survey: no survey columns.
    expect(Object.keys(csvRows(exportCsv(input({ survey: null, assignment: null })))[0]).some((column) => column.startsWith('survey_'))).toBe(false);
  });

  it('writes a code of digits in quotes and reads it back with its zeros', () => {
    const digits = exportCsv(input({ participant: '007' }));
    expect(digits).toContain('\r\n"007",');
    expect(csvRows(digits)[0]).toMatchObject({ learner_id: '007', participant: '007' });
  });

  it('leaves hidden-tab time out of active time', () => {
    const [orbit, select1] = csvRows(text);
    expect(orbit.active_ms).toBe('10000');
    expect(select1.active_ms).toBe('9000');
  });

  it('leaves participant and assignment empty in anonymous free play', () => {
    const [first] = csvRows(exportCsv(input({ participant: null, assignment: null })));
    expect(first).toMatchObject({ participant: '', assignment: '', assignment_id: '', learner_id: `install:${INSTALL}` });
  });
});

describe('JSON export', () => {
  it('holds the full log, the app version, the assignment and the survey', () => {
    const data = buildExport(input());
    expect(data).toMatchObject({ format: EXPORT_FORMAT, version: 1, appVersion: '9.9.9', exportedAt: '2025-03-04T10:01:00.000Z', participant: 'P-07, ü' });
    expect(data.learner).toEqual({ id: 'P-07, ü', installId: INSTALL, attemptId: ATTEMPT });
    expect(data.assignment).toEqual({ id: assignmentId(assignment), ...assignment });
    expect(data.events).toEqual({ startedAt: START, events });
    expect(data.progress.points).toBe(10);
    // The CSV's rows, for a reader who wants per-task figures without reading the events.
    expect(
      data.attempts.map(({ task, hintsText, hintsGuidance, hintsOffered, hintsOpened }) => ({ task, hintsText, hintsGuidance, hintsOffered, hintsOpened })),
    ).toEqual([
      { task: 'orbit', hintsText: 1, hintsGuidance: 0, hintsOffered: 0, hintsOpened: 1 },
      { task: 'select', hintsText: 0, hintsGuidance: 0, hintsOffered: 1, hintsOpened: 0 },
      { task: 'select', hintsText: 1, hintsGuidance: 0, hintsOffered: 1, hintsOpened: 1 },
      { task: 'extra', hintsText: 0, hintsGuidance: 0, hintsOffered: 0, hintsOpened: 0 },
      { task: 'guess', hintsText: 0, hintsGuidance: 0, hintsOffered: 1, hintsOpened: 0 },
      { task: 'read', hintsText: 0, hintsGuidance: 0, hintsOffered: 0, hintsOpened: 0 },
    ]);
    expect(data.survey?.answers).toEqual({ 'computer-skill': 7, feedback: 'Nice, "really"' });
    expect(data.utcOffsetMin).toBe(-330);
    expect(data.attempts.find((attempt) => attempt.task === 'guess')).toMatchObject({ quizChoice: 2, quizChoiceId: 'c', quizChoiceText: 'l1/guess option 2' });
    expect(data.attempts.find((attempt) => attempt.task === 'orbit')).toMatchObject({ quizChoice: null, quizChoiceId: null, quizChoiceText: null });
    expect(data.attempts.map((attempt) => attempt.explanationOpens)).toEqual([0, 0, 1, 0, 0, 0]);
  });

  it('knows the app version from package.json', () => {
    expect(APP_VERSION).toMatch(/^\d+\.\d+\.\d+/);
  });
});

describe('ISO 8601 durations', () => {
  it.each([
    [0, 'PT0S'],
    [4, 'PT0S'],
    [5, 'PT0.01S'],
    [1_000, 'PT1S'],
    [63_500, 'PT1M3.5S'],
    [60_000, 'PT1M'],
    [3_600_000, 'PT1H'],
    [3_723_450, 'PT1H2M3.45S'],
    [59_999, 'PT1M'],
    [90_000_000, 'PT25H'],
  ])('%d ms is %s', (ms, text) => expect(isoDuration(ms)).toBe(text));

  it('refuses negative and non-finite durations', () => {
    expect(() => isoDuration(-1)).toThrow(RangeError);
    expect(() => isoDuration(Number.NaN)).toThrow(RangeError);
  });

  it('turns log times into UTC times', () => {
    expect(isoAt(START, 1_234)).toBe('2025-03-04T09:00:01.234Z');
  });
});

describe('xAPI export', () => {
  const statements = exportXapi(input());

  it('gives every statement an id, actor, verb, activity and ISO 8601 timestamp', () => {
    expect(statements.length).toBeGreaterThan(10);
    for (const statement of statements) {
      expect(statement.id).toMatch(/^[0-9a-f]{8}-[0-9a-f]{4}-8[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}$/);
      expect(statement.actor).toEqual({ objectType: 'Agent', account: { homePage: 'https://raytracerquest.example', name: 'P-07, ü' } });
      expect(statement.verb.id).toMatch(/^http:\/\/(adlnet\.gov\/expapi|id\.tincanapi\.com)\/verb/);
      expect(statement.verb.display['en-US']).toBeTruthy();
      expect(statement.object.objectType).toBe('Activity');
      expect(statement.object.id).toMatch(/^https:\/\/raytracerquest\.example/);
      expect(new Date(statement.timestamp).toISOString()).toBe(statement.timestamp);
      expect(statement.context.language).toBe('nl');
      expect(statement.context.registration).toBe(ATTEMPT);
      if (statement.result?.duration) expect(statement.result.duration).toMatch(/^PT(\d+H)?(\d+M)?(\d+(\.\d+)?S)?$/);
    }
    expect(new Set(statements.map((s) => s.id)).size).toBe(statements.length);
  });

  it('reports task completions with success, score and duration', () => {
    const completed = statements.filter((s) => s.verb.id === 'http://adlnet.gov/expapi/verbs/completed' && s.object.id.includes('/tasks/'));
    expect(completed.map((s) => [s.object.id.split('/').at(-1), s.result?.success, s.result?.score?.raw, s.result?.duration])).toEqual([
      ['orbit', true, 10, 'PT30S'],
      ['select', false, 0, 'PT3.5S'],
      // Answered wrong: completed, not a success.
      ['guess', false, 5, 'PT1S'],
    ]);
    expect(
      completed.map((s) => [
        s.result?.extensions?.['https://raytracerquest.example/extensions/hints-offered'],
        s.result?.extensions?.['https://raytracerquest.example/extensions/hints-opened'],
      ]),
    ).toEqual([
      [0, 1],
      [1, 1],
      [1, 0],
    ]);
    expect(completed[0].object.id).toBe('https://raytracerquest.example/levels/l1/tasks/orbit');
    expect(completed[0].context.contextActivities.parent?.[0].id).toBe('https://raytracerquest.example/levels/l1');
    expect(statements.some((s) => s.verb.id === 'http://id.tincanapi.com/verb/skipped')).toBe(true);
  });

  it('reports each hint shown with its trigger, and no statement for an offer', () => {
    const hints = statements.filter((s) => s.object.id.includes('/hints/'));
    expect(hints.map((s) => [s.object.id.split('/tasks/')[1], s.result?.extensions?.['https://raytracerquest.example/extensions/trigger']])).toEqual([
      ['orbit/hints/text', 'asked'],
      ['select/hints/guidance', 'idle'],
      ['select/hints/text', 'offered'],
    ]);
  });

  it('reports quiz answers, the passed level, and the survey answers', () => {
    const quiz = statements.find((s) => s.verb.id.endsWith('/answered') && s.object.id.endsWith('/tasks/guess'));
    // A choice interaction's response is the option's id; its text rides along in an extension.
    expect(quiz?.result).toEqual({
      success: false,
      response: 'c',
      extensions: { 'https://raytracerquest.example/extensions/choice-text': 'l1/guess option 2' },
    });
    expect(quiz?.context.extensions).toEqual({
      'https://raytracerquest.example/extensions/app-version': '9.9.9',
      'https://raytracerquest.example/extensions/utc-offset-min': '-330',
    });
    const passed = statements.find((s) => s.verb.id.endsWith('/passed'));
    expect(passed?.result).toMatchObject({ success: true, duration: 'PT4S' });
    const answer = statements.find((s) => s.object.id.endsWith('/questions/computer-skill'));
    expect(answer?.result?.response).toBe('7');
  });

  it('keeps the statements in time order and the same ids for the same file', () => {
    const times = statements.map((s) => Date.parse(s.timestamp));
    expect(times).toEqual([...times].sort((a, b) => a - b));
    expect(exportXapi(input()).map((s) => s.id)).toEqual(statements.map((s) => s.id));
  });

  it('names an anonymous learner by an account of their own', () => {
    const [first] = exportXapi(input({ participant: null, assignment: null }));
    expect(first.actor.account.name).toBe(`install:${INSTALL}`);
    expect(first.context.language).toBe('en');
  });

  it("uses the school's home page for accounts and tells two playthroughs apart", () => {
    const school = exportXapi(input({ assignment: { ...assignment, xapiHomePage: 'https://school.example' } }));
    expect(new Set(school.map((s) => s.actor.account.homePage))).toEqual(new Set(['https://school.example']));
    const again = exportXapi(input({ attemptId: '66666666-7777-4888-9999-bbbbbbbbbbbb' }));
    expect(again.every((s) => s.context.registration === '66666666-7777-4888-9999-bbbbbbbbbbbb')).toBe(true);
    // Same code, same moments, another attempt: no statement id is shared, so a store keeps both.
    const ids = new Set(statements.map((s) => s.id));
    expect(again.some((s) => ids.has(s.id))).toBe(false);
  });
});
