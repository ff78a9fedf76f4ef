import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { ATTEMPT_COLUMN_MEANINGS } from '../../src/classroom/attempt-column-meanings.ts';
import { ATTEMPT_COLUMNS } from '../../src/classroom/attempt-columns.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import { codebookMarkdown } from '../../src/classroom/dashboard-codebook.ts';
import { classLearners } from '../../src/classroom/dashboard-learners.ts';
import { LEARNER_LEVEL_COLUMNS, learnerLevelCsv } from '../../src/classroom/dashboard-learner-levels.ts';
import { summarizeQuizzes } from '../../src/classroom/dashboard-quiz.ts';
import type { ClassRecord } from '../../src/classroom/dashboard-record.ts';
import { choiceQuestions } from '../../src/classroom/quiz-options.ts';
import { surveyById } from '../../src/classroom/surveys.ts';
import type { TaskAttempt } from '../../src/classroom/task-attempts.ts';
import { loadLevels, playableLevels } from '../../src/quest/level-index.ts';

const levelsFolder = new URL('../../levels/', import.meta.url);
const levels = playableLevels(
  loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8')),
);
const questions = choiceQuestions(levels, 'en');
// Level 2's first quiz: "A primary ray from the camera hits the floor. What does the ray tracer do next?"
const quiz = questions.find((question) => question.level === '02-rays-from-the-camera' && question.task === 'predict-light-path')!;
const wrong = [0, 1, 2].find((position) => position !== quiz.answer)!;

const attempt = (task: string, extra: Partial<TaskAttempt> = {}): TaskAttempt => ({
  level: '02-rays-from-the-camera',
  task,
  mandatory: true,
  kind: 'quiz',
  startedAt: '2026-03-09T09:00:00.000Z',
  completedAt: '2026-03-09T09:01:00.000Z',
  durationMs: 60_000,
  activeMs: 50_000,
  how: 'done',
  points: 10,
  hintsText: 0,
  hintsGuidance: 0,
  hintsOffered: 0,
  quizAnswers: 1,
  quizCorrect: null,
  quizChoice: null,
  explanationOpens: 0,
  ...extra,
});

const record = (participant: string, attempts: TaskAttempt[]): ClassRecord => ({
  file: `${participant}.json`,
  participant,
  learnerId: participant,
  attemptId: `attempt-${participant}`,
  installId: '',
  assignment: 'Lesson',
  assignmentId: 'abc',
  classCode: '5H2',
  appVersion: '1.0.0',
  utcOffsetMin: '60',
  attempts,
  visits: [],
  survey: null,
});

const answer = (choice: number, extra: Partial<TaskAttempt> = {}) =>
  attempt('predict-light-path', { quizChoice: choice, quizCorrect: choice === quiz.answer, points: choice === quiz.answer ? 10 : 0, ...extra });

/** Four learners: two right, one wrong, one wrong first and right on a second visit (counted by the first answer); one never answered. */
const learners = classLearners([
  record('P1', [answer(quiz.answer)]),
  record('P2', [answer(quiz.answer, { hintsOffered: 2, hintsText: 1, explanationOpens: 3 })]),
  record('P3', [answer(wrong)]),
  record('P4', [answer(wrong), answer(quiz.answer)]),
  record('P5', [attempt('the-screen', { kind: 'info', mandatory: false, quizAnswers: 0 })]),
]);

describe('quiz results per question', () => {
  it('count each learner once, by their first answer: n, share right, and each option', () => {
    const [summary, ...others] = summarizeQuizzes(learners, questions);
    expect(others).toEqual([]);
    expect(summary).toMatchObject({ level: quiz.level, task: quiz.task, question: quiz.question, learners: 4, right: 2 });
    expect(summary.options.map((option) => option.learners)).toEqual(
      quiz.options.map((_, position) => (position === quiz.answer ? 2 : position === wrong ? 2 : 0)),
    );
    expect(summary.options[wrong]).toMatchObject({ text: quiz.options[wrong], right: false });
  });
});

describe('the per-learner × level table', () => {
  it('has one row per learner and level, with the sums of their attempts', () => {
    const parsed = parseCsv(learnerLevelCsv(learners, ['01-introduction', '02-rays-from-the-camera']));
    if (!parsed.ok) throw new Error(parsed.error);
    const [header, ...rows] = parsed.rows;
    expect(header).toEqual(LEARNER_LEVEL_COLUMNS.map((column) => column.name));
    const byLearner = Object.fromEntries(rows.map((row) => [row[0], Object.fromEntries(header.map((name, index) => [name, row[index]]))]));
    expect(Object.keys(byLearner)).toEqual(['P1', 'P2', 'P3', 'P4', 'P5']);
    expect(byLearner.P2).toMatchObject({
      level: '02-rays-from-the-camera',
      class_code: '5H2',
      hints_offered: '2',
      hints_opened: '1',
      explanation_opens: '3',
      quiz_right: '1',
    });
    expect(byLearner.P4).toMatchObject({ task_attempts: '2', tasks_done: '1', quiz_answers: '2', quiz_right: '1', points: '10', active_ms: '100000' });
    expect(byLearner.P5).toMatchObject({ quiz_answers: '0', tasks_done: '1', passed: 'true' });
  });
});

describe('the codebook', () => {
  const survey = surveyById('default')!;
  const text = codebookMarkdown({
    appVersion: '1.2.3',
    madeAt: '2026-03-09T10:00:00.000Z',
    locale: 'nl',
    questions: choiceQuestions(levels, 'nl'),
    surveys: [survey],
  });

  // A Markdown cell escapes "|" and "<" (install:<id> is no HTML tag).
  const md = (text: string) => text.replace(/([|<])/g, '\\$1');

  it('gives every column of both tables a meaning and a unit', () => {
    for (const column of ATTEMPT_COLUMNS) {
      expect(ATTEMPT_COLUMN_MEANINGS[column.name], column.name).toBeDefined();
      expect(text).toContain(`| \`${column.name}\` | ${md(ATTEMPT_COLUMN_MEANINGS[column.name].meaning)} | ${md(ATTEMPT_COLUMN_MEANINGS[column.name].unit)} |`);
    }
    expect(Object.keys(ATTEMPT_COLUMN_MEANINGS)).toEqual(ATTEMPT_COLUMNS.map((column) => column.name));
    for (const column of LEARNER_LEVEL_COLUMNS) expect(text).toContain(`| \`${column.name}\` | ${md(column.meaning)} | ${md(column.unit)} |`);
  });

  it('lists every quiz question with its options by id and text, in the chosen language', () => {
    const dutch = choiceQuestions(levels, 'nl').find((question) => question.task === quiz.task && question.level === quiz.level)!;
    expect(text).toContain(`### ${quiz.level} / ${quiz.task}\n\n${dutch.question}`);
    expect(text).toContain(`| ${String.fromCharCode(0x61 + quiz.answer)} | ${dutch.options[quiz.answer]} | yes |`);
    expect(text.match(/^### \d\d-/gm)?.length).toBe(choiceQuestions(levels, 'nl').length);
  });

  it('lists every survey question with its options or scale ends', () => {
    for (const question of survey.questions) {
      expect(text).toContain(`### \`survey_${question.id}\``);
      if (question.type === 'choice') for (const option of question.options) expect(text).toContain(`| ${option.id} |`);
      if (question.type === 'scale') expect(text).toContain(`from ${question.min} (`);
    }
  });

  it('says which survey questions are asked only with some levels, and that the teacher may choose otherwise', () => {
    const soft = survey.questions.find((question) => question.id === 'learned-soft-shadows');
    expect(soft?.levels).toEqual(['10-area-lights']);
    expect(text).toMatch(
      /### `survey_learned-soft-shadows`[^#]*Asked by default only in assignments with one of the levels `10-area-lights`; the teacher may tick it on or off/,
    );
    expect(text).not.toMatch(/### `survey_age`[^#]*Asked by default only/);
  });
});
