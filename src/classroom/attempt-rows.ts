import type { TaskAttempt } from './task-attempts.ts';

/**
 * A learner's task attempts as rows of the CSV export's columns (spec/classroom.md), shared
 * by the learner's own CSV export and the dashboard's combined CSV so that the two files
 * always agree. `attempts` is the attempt's number for its task (1, 2, …).
 */

export const CSV_COLUMNS = [
  'participant',
  'assignment',
  'assignment_id',
  'level',
  'task',
  'mandatory',
  'started_at',
  'completed_at',
  'duration_ms',
  'active_ms',
  'how',
  'hints_text',
  'hints_guidance',
  'shown_by_app',
  'attempts',
  'quiz_answers',
  'points',
] as const;

export type CsvCell = string | number | boolean;

/** Who the attempts belong to: '' for no participant code or no assignment. */
export interface AttemptOwner {
  participant: string;
  assignment: string;
  assignmentId: string;
}

export function attemptRows(owner: AttemptOwner, attempts: readonly TaskAttempt[]): CsvCell[][] {
  const tries = new Map<string, number>();
  return attempts.map((attempt) => {
    const key = `${attempt.level}/${attempt.task}`;
    const number = (tries.get(key) ?? 0) + 1;
    tries.set(key, number);
    return [
      owner.participant,
      owner.assignment,
      owner.assignmentId,
      attempt.level,
      attempt.task,
      attempt.mandatory,
      attempt.startedAt,
      attempt.completedAt ?? '',
      attempt.durationMs,
      attempt.activeMs,
      attempt.how ?? '',
      attempt.hintsText,
      attempt.hintsGuidance,
      attempt.how === 'shown',
      number,
      attempt.quizAnswers,
      attempt.points,
    ];
  });
}
