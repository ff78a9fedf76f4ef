import { ID_COLUMNS, type CsvCell } from './attempt-columns.ts';
import { csvTable } from './csv-text.ts';
import type { ClassLearner } from './dashboard-learners.ts';
import { learnerInLevel } from './dashboard-summary.ts';
import { hintsOpened, type TaskAttempt } from './task-attempts.ts';

/**
 * The per-learner × level table: one row per learner and level they opened, the shape a
 * researcher's analysis usually starts from (the CSV export has one row per task attempt).
 * Each column is declared once, with its meaning and unit, so that the codebook
 * (dashboard-codebook.ts) describes exactly the columns written.
 */

export interface LearnerLevelColumn {
  name: string;
  meaning: string;
  unit: string;
  value(learner: ClassLearner, level: string, attempts: readonly TaskAttempt[]): CsvCell;
}

const sum = (attempts: readonly TaskAttempt[], of: (attempt: TaskAttempt) => number) => attempts.reduce((total, attempt) => total + of(attempt), 0);
const count = (attempts: readonly TaskAttempt[], test: (attempt: TaskAttempt) => boolean) => attempts.filter(test).length;
/** Tasks (not attempts) of the level that ended this way in some attempt. */
const tasksWhere = (attempts: readonly TaskAttempt[], test: (attempt: TaskAttempt) => boolean) =>
  new Set(attempts.filter(test).map((attempt) => attempt.task)).size;

export const LEARNER_LEVEL_COLUMNS: readonly LearnerLevelColumn[] = [
  {
    name: 'learner_id',
    meaning: 'the learner (participant code, or install:<id> without one), as in the CSV export',
    unit: 'text',
    value: (learner) => learner.learnerId,
  },
  { name: 'participant', meaning: 'the participant code as typed, or empty', unit: 'text', value: (learner) => learner.participant },
  { name: 'assignment_id', meaning: "the assignment's id, or empty in free play", unit: 'text', value: (learner) => learner.assignmentId },
  { name: 'class_code', meaning: "the assignment's class code, or empty", unit: 'text', value: (learner) => learner.classCode },
  { name: 'level', meaning: "the level's id", unit: 'text', value: (_, level) => level },
  {
    name: 'passed',
    meaning: 'whether the learner passed the level (from a CSV export: every required task completed)',
    unit: 'true/false',
    value: (learner, level) => learnerInLevel(learner, level)?.passed ?? false,
  },
  {
    name: 'active_ms',
    meaning: 'time in the level with the tab visible, over all visits (from a CSV export: the sum of its task attempts)',
    unit: 'milliseconds',
    value: (learner, level) => learnerInLevel(learner, level)?.activeMs ?? 0,
  },
  {
    name: 'task_attempts',
    meaning: 'task attempts in the level (a task left and taken up again is two)',
    unit: 'count',
    value: (_, __, attempts) => attempts.length,
  },
  {
    name: 'tasks_done',
    meaning: 'tasks the learner completed themselves',
    unit: 'count of tasks',
    value: (_, __, attempts) => tasksWhere(attempts, (attempt) => attempt.how === 'done'),
  },
  {
    name: 'tasks_shown',
    meaning: 'tasks completed by "Show me"',
    unit: 'count of tasks',
    value: (_, __, attempts) => tasksWhere(attempts, (attempt) => attempt.how === 'shown'),
  },
  {
    name: 'tasks_skipped',
    meaning: 'optional tasks left out',
    unit: 'count of tasks',
    value: (_, __, attempts) => tasksWhere(attempts, (attempt) => attempt.how === 'skipped'),
  },
  {
    name: 'hints_offered',
    meaning: 'hints offered after idle time, opened or not',
    unit: 'count',
    value: (_, __, attempts) => sum(attempts, (attempt) => attempt.hintsOffered),
  },
  {
    name: 'hints_opened',
    meaning: 'text hints and "show me where" rings the learner opened',
    unit: 'count',
    value: (_, __, attempts) => sum(attempts, hintsOpened),
  },
  {
    name: 'explanation_opens',
    meaning: '"Explain more" opened for the level\'s tasks',
    unit: 'count',
    value: (_, __, attempts) => sum(attempts, (attempt) => attempt.explanationOpens),
  },
  {
    name: 'quiz_answers',
    meaning: 'quiz answers given (predictions: choices and numbers)',
    unit: 'count',
    value: (_, __, attempts) => sum(attempts, (attempt) => attempt.quizAnswers),
  },
  {
    name: 'quiz_right',
    meaning: 'quiz answers that were right',
    unit: 'count',
    value: (_, __, attempts) => count(attempts, (attempt) => attempt.quizAnswers > 0 && attempt.quizCorrect === true),
  },
  { name: 'points', meaning: 'points earned in the level', unit: 'points', value: (_, __, attempts) => sum(attempts, (attempt) => attempt.points) },
];

/** The table as CSV text (without the byte-order mark, which the download adds). */
export function learnerLevelCsv(learners: readonly ClassLearner[], levels: readonly string[]): string {
  const rows = learners.flatMap((learner) =>
    levels.flatMap((level) => {
      if (!learnerInLevel(learner, level)) return [];
      const attempts = learner.attempts.filter((attempt) => attempt.level === level);
      return [LEARNER_LEVEL_COLUMNS.map((column) => column.value(learner, level, attempts))];
    }),
  );
  return csvTable(
    LEARNER_LEVEL_COLUMNS.map((column) => column.name),
    rows,
    ID_COLUMNS,
  );
}
