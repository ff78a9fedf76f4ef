import { ATTEMPT_COLUMNS, SURVEY_PREFIX, type AttemptOwner, type CsvCell } from './attempt-columns.ts';
import type { OptionText } from './quiz-options.ts';
import type { TaskAttempt } from './task-attempts.ts';

/**
 * A learner's task attempts as rows of the CSV export's columns (attempt-columns.ts;
 * docs/classroom.md defines each), shared by the learner's own CSV export and the
 * dashboard's combined CSV so that the two files always agree.
 *
 * The survey's answers follow as one `survey_<question>` column per question, repeated on
 * each of the learner's rows (a researcher keeps one row per attempt_id for them).
 */

/** The header: the table's columns, then one per survey question. */
export function csvHeader(surveyQuestions: readonly string[]): string[] {
  return [...ATTEMPT_COLUMNS.map((column) => column.name), ...surveyQuestions.map((question) => `${SURVEY_PREFIX}${question}`)];
}

export function attemptRows(owner: AttemptOwner, attempts: readonly TaskAttempt[], surveyQuestions: readonly string[], optionText: OptionText): CsvCell[][] {
  const tries = new Map<string, number>();
  const answers = surveyQuestions.map((question) => owner.survey?.answers[question] ?? '');
  return attempts.map((attempt) => {
    const key = `${attempt.level}/${attempt.task}`;
    const number = (tries.get(key) ?? 0) + 1;
    tries.set(key, number);
    return [...ATTEMPT_COLUMNS.map((column) => column.value({ owner, attempt, number, optionText })), ...answers];
  });
}
