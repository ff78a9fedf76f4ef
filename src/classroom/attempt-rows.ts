import type { SurveyAnswers } from './survey-answers.ts';
import { hintsOpened, type TaskAttempt } from './task-attempts.ts';

/**
 * A learner's task attempts as rows of the CSV export's columns (docs/classroom.md defines
 * each), shared by the learner's own CSV export and the dashboard's combined CSV so that
 * the two files always agree. `attempts` is the attempt's number for its task (1, 2, …).
 *
 * The survey's answers follow as one `survey_<question>` column per question, repeated on
 * each of the learner's rows (a researcher keeps one row per attempt_id for them).
 */

export const CSV_COLUMNS = [
  'learner_id',
  'attempt_id',
  'install_id',
  'participant',
  'assignment',
  'assignment_id',
  'class_code',
  'level',
  'task',
  'kind',
  'mandatory',
  'started_at',
  'completed_at',
  'duration_ms',
  'active_ms',
  'how',
  'hints_text',
  'hints_guidance',
  'hints_offered',
  'hints_opened',
  'shown_by_app',
  'attempts',
  'quiz_answers',
  'quiz_correct',
  'points',
  'survey',
] as const;

/**
 * Identifiers: always written in quotes, so that a reader told to keep quoted fields as text
 * (LibreOffice's "Format quoted field as text", Python's csv.QUOTE_NONNUMERIC) keeps "007".
 */
export const ID_COLUMNS: ReadonlySet<string> = new Set(['learner_id', 'attempt_id', 'install_id', 'participant', 'assignment_id', 'class_code']);

export const SURVEY_PREFIX = 'survey_';

export type CsvCell = string | number | boolean;

/** Who the attempts belong to: '' for no participant code, no assignment, no class code. */
export interface AttemptOwner {
  learnerId: string;
  attemptId: string;
  installId: string;
  participant: string;
  assignment: string;
  assignmentId: string;
  classCode: string;
  survey: { id: string; answers: SurveyAnswers } | null;
}

/** The header: the fixed columns, then one per survey question. */
export function csvHeader(surveyQuestions: readonly string[]): string[] {
  return [...CSV_COLUMNS, ...surveyQuestions.map((question) => `${SURVEY_PREFIX}${question}`)];
}

export function attemptRows(owner: AttemptOwner, attempts: readonly TaskAttempt[], surveyQuestions: readonly string[]): CsvCell[][] {
  const tries = new Map<string, number>();
  const answers = surveyQuestions.map((question) => owner.survey?.answers[question] ?? '');
  return attempts.map((attempt) => {
    const key = `${attempt.level}/${attempt.task}`;
    const number = (tries.get(key) ?? 0) + 1;
    tries.set(key, number);
    return [
      owner.learnerId,
      owner.attemptId,
      owner.installId,
      owner.participant,
      owner.assignment,
      owner.assignmentId,
      owner.classCode,
      attempt.level,
      attempt.task,
      attempt.kind ?? '',
      attempt.mandatory,
      attempt.startedAt,
      attempt.completedAt ?? '',
      attempt.durationMs,
      attempt.activeMs,
      attempt.how ?? '',
      attempt.hintsText,
      attempt.hintsGuidance,
      attempt.hintsOffered,
      hintsOpened(attempt),
      attempt.how === 'shown',
      number,
      attempt.quizAnswers,
      attempt.quizCorrect ?? '',
      attempt.points,
      owner.survey?.id ?? '',
      ...answers,
    ];
  });
}
