import { describe, expect, it } from 'vitest';
import type { TaskAttempt } from '../../src/classroom/task-attempts.ts';
import { readClassFiles, combinedCsv } from '../../src/classroom/dashboard-class.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import type { ClassRecord } from '../../src/classroom/dashboard-record.ts';
import { completionRate, isOptionalTask, summarizeLevels } from '../../src/classroom/dashboard-summary.ts';
import { summarizeSurveys } from '../../src/classroom/dashboard-survey.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import { simulatedClassFiles } from '../support/class-exports.ts';

const attempt = (task: string, activeMs: number, how: TaskAttempt['how'], extra: Partial<TaskAttempt> = {}): TaskAttempt => ({
  level: '02-b',
  task,
  mandatory: true,
  kind: 'do',
  startedAt: '2026-03-09T09:00:00.000Z',
  completedAt: how ? '2026-03-09T09:01:00.000Z' : null,
  durationMs: activeMs,
  activeMs,
  how,
  points: how === 'done' ? 10 : 0,
  hintsText: 0,
  hintsGuidance: 0,
  hintsOffered: 0,
  quizAnswers: 0,
  quizCorrect: null,
  quizChoice: null,
  explanationOpens: 0,
  ...extra,
});

const record = (participant: string, attempts: TaskAttempt[], passed: boolean | null, survey: ClassRecord['survey'] = null): ClassRecord => ({
  file: `${participant}.json`,
  participant,
  learnerId: participant,
  attemptId: `attempt-${participant}`,
  installId: '',
  assignment: 'Lesson',
  assignmentId: 'abc',
  classCode: '',
  appVersion: '',
  utcOffsetMin: '',
  attempts,
  visits: passed === null ? [] : [{ level: '02-b', durationMs: 100_000, activeMs: 90_000, passed }],
  survey,
});

describe('the class summary', () => {
  const records = [
    // Needed two attempts (left the level once) and two hints.
    record('P1', [attempt('x', 20_000, null, { hintsText: 1 }), attempt('x', 10_000, 'done', { hintsGuidance: 1 })], true),
    record('P2', [attempt('x', 40_000, 'shown', { hintsText: 1 })], true),
    // Offered a hint after idle time and did not open it: no help needed.
    record('P3', [attempt('x', 60_000, 'done', { hintsOffered: 1 }), attempt('y', 5000, 'skipped', { mandatory: false })], false),
    record('P4', [attempt('x', 99_000, null)], false),
  ];

  it('counts per task: learners, how they finished, hints, and the times of those who completed', () => {
    const [level] = summarizeLevels(records);
    const [x, y] = level.tasks;
    expect(x).toMatchObject({
      task: 'x',
      mandatory: true,
      learners: 4,
      done: 2,
      shown: 1,
      skipped: 0,
      hintsText: 2,
      hintsGuidance: 1,
      learnersWithHints: 2,
      learnersNeedingHelp: 3,
    });
    expect(x.times).toEqual([30_000, 40_000, 60_000]);
    expect(x.stats).toMatchObject({ median: 40_000, q1: 35_000, q3: 50_000 });
    expect(completionRate(x)).toBe(0.75);
    expect(y).toMatchObject({ task: 'y', mandatory: false, learners: 1, skipped: 1, times: [], learnersNeedingHelp: 0 });
    expect(y.stats).toBeNull();
  });

  it('counts per level: learners, passes, and the active time of those who passed', () => {
    expect(summarizeLevels(records)[0]).toMatchObject({ level: '02-b', learners: 4, passed: 2, times: [90_000, 90_000] });
  });

  it('without level events (a CSV export), passing is completing every mandatory task', () => {
    const fromCsv = [
      record('P1', [attempt('x', 1000, null), attempt('x', 2000, 'done'), attempt('y', 1, null, { mandatory: false })], null),
      record('P2', [attempt('x', 1000, null)], null),
    ];
    expect(summarizeLevels(fromCsv)[0]).toMatchObject({ learners: 2, passed: 1, times: [3001] });
  });

  it('sorts levels by their number', () => {
    const levels = summarizeLevels([record('P1', [attempt('x', 1, 'done', { level: '10-late' }), attempt('x', 1, 'done', { level: '02-early' })], null)]);
    expect(levels.map((level) => level.level)).toEqual(['02-early', '10-late']);
  });

  it('counts survey answers per step, option and number; lists remarks; names unknown surveys', () => {
    const answers = (value: number, extra = {}) => ({
      id: 'default',
      answers: { 'learned-soft-shadows': value, ease: 'about-right', minutes: value * 10, ...extra },
    });
    const { surveys, unknown } = summarizeSurveys(
      [
        record('P1', [], null, answers(5, { feedback: 'Great' })),
        record('P2', [], null, answers(5)),
        record('P3', [], null, answers(2)),
        record('P4', [], null, { id: 'old-survey', answers: {} }),
        record('P5', [], null, answers(9)),
      ],
      surveyById,
    );
    expect(unknown).toEqual([{ id: 'old-survey', respondents: 1 }]);
    const [survey] = surveys;
    expect(survey.respondents).toBe(4);
    const shadows = survey.scales.find((scale) => scale.id === 'learned-soft-shadows');
    // 9 is outside the 1–5 scale (a hand-edited file): not counted.
    expect(shadows).toMatchObject({ min: 1, max: 5, counts: [0, 1, 0, 0, 2], answered: 3 });
    expect(survey.choices.find((choice) => choice.id === 'ease')?.options.map((option) => option.count)).toEqual([0, 4, 0]);
    expect(survey.numbers.find((number) => number.id === 'minutes')?.stats).toMatchObject({ count: 4, median: 50 });
    expect(survey.texts.find((text) => text.id === 'feedback')?.answers).toEqual(['Great']);
  });
});

describe('a class of files', () => {
  const files = simulatedClassFiles(30);

  it('reads 30 exports, skips a damaged file and a duplicate with their reasons', () => {
    const read = readClassFiles([
      ...files,
      { name: 'broken.json', text: '{"format": "ray-tracer-quest-export", ' },
      { name: 'copy.json', text: files[3].text },
    ]);
    expect(read.records).toHaveLength(30);
    expect(read.skipped).toEqual([
      { file: 'broken.json', reason: 'the file is damaged', detail: { path: '(root)', reason: expect.objectContaining({ code: 'notJson', line: 1 }) } },
      { file: 'copy.json', reason: `the same export as ${files[3].name}, counted once` },
    ]);
  });

  it('adds a second drop to the first', () => {
    const first = readClassFiles(files.slice(0, 10));
    const both = readClassFiles(files.slice(10), first);
    expect(both.records.map((item) => item.participant)).toEqual(readClassFiles(files).records.map((item) => item.participant));
  });

  it('writes every attempt of every learner as one CSV row, with the file it came from', () => {
    const { records } = readClassFiles(files);
    const csv = parseCsv(combinedCsv(classLearners(records), surveyById));
    if (!csv.ok) throw new Error(csv.error);
    const [header, ...rows] = csv.rows;
    expect(header.slice(0, 7)).toEqual(['learner_id', 'attempt_id', 'install_id', 'participant', 'assignment', 'assignment_id', 'class_code']);
    expect(header.at(-1)).toBe('file');
    expect(header).toContain('survey_computer-skill');
    expect(rows).toHaveLength(records.reduce((total, item) => total + item.attempts.length, 0));
    expect(rows[0].at(-1)).toBe(files[0].name);
    expect(new Set(rows.map((row) => row[0])).size).toBe(30);
  });
});

describe('optional tasks on the dashboard', () => {
  it('are the ones a learner could leave out: an info step is read, never "optional"', () => {
    const [level] = summarizeLevels([
      record(
        'P1',
        [
          attempt('intro', 1000, null, { kind: 'info', mandatory: false }),
          attempt('extra', 1000, 'skipped', { mandatory: false }),
          attempt('main', 1000, 'done'),
        ],
        true,
      ),
    ]);
    const optional = Object.fromEntries(level.tasks.map((task) => [task.task, isOptionalTask(task)]));
    expect(optional).toEqual({ intro: false, extra: true, main: false });
  });
});
