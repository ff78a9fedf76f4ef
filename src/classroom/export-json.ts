import type { EventLogData } from '../quest/event-log.ts';
import { pointsOf, type Progress } from '../quest/progress.ts';
import type { Assignment } from './assignment.ts';
import { assignmentId } from './assignment-id.ts';
import type { ExportInput } from './export-context.ts';
import { learnerId } from './learner-identity.ts';
import { NO_OPTION_TEXTS, optionId, type OptionText } from './quiz-options.ts';
import { hintsOpened, readLog, type TaskAttempt } from './task-attempts.ts';
import type { SurveySubmission } from './survey-answers.ts';
import { conceptTestExport, type ConceptTestExport } from './concept-test/concept-test-export.ts';

/**
 * The JSON export: everything a researcher (or the class dashboard) needs from one
 * learner, in one file. `events` is the complete event log, never shortened: `t` is
 * milliseconds since `events.startedAt` on the monotonic clock (src/quest/event-log.ts).
 * `attempts` are the CSV's rows read from that log (task-attempts.ts), for a reader who
 * wants the per-task figures without reading events; the dashboard reads the events.
 */

/** A task attempt as the CSV has it, with the hints it counts as used and the chosen option's id and text (quiz-options.ts). */
export type ExportedAttempt = TaskAttempt & { hintsOpened: number; quizChoiceId: string | null; quizChoiceText: string | null };

export const EXPORT_FORMAT = 'ray-tracer-quest-export';
export const EXPORT_VERSION = 1;

export interface QuestExport {
  format: typeof EXPORT_FORMAT;
  version: typeof EXPORT_VERSION;
  appVersion: string;
  exportedAt: string;
  /** Minutes the device's clock was ahead of UTC at the download, or null when unknown (export-context.ts). */
  utcOffsetMin: number | null;
  participant: string | null;
  /** Who and which playthrough (learner-identity.ts): the dashboard merges a learner's files by these. */
  learner: { id: string; installId: string; attemptId: string };
  /** The assignment with its id, or null in free play. */
  assignment: (Assignment & { id: string }) | null;
  progress: { points: number; levels: Progress['levels']; badges: Progress['badges'] };
  events: EventLogData;
  attempts: ExportedAttempt[];
  survey: SurveySubmission | null;
  conceptTest: ConceptTestExport | null;
}

export function buildExport(input: ExportInput): QuestExport {
  const { progress, assignment } = input;
  return {
    format: EXPORT_FORMAT,
    version: EXPORT_VERSION,
    appVersion: input.appVersion,
    exportedAt: input.exportedAt,
    utcOffsetMin: input.utcOffsetMin ?? null,
    participant: input.participant,
    learner: { id: learnerId(input.participant, input.installId), installId: input.installId, attemptId: input.attemptId },
    assignment: assignment ? { id: assignmentId(assignment), ...assignment } : null,
    progress: { points: pointsOf(progress), levels: progress.levels, badges: progress.badges },
    events: progress.log,
    attempts: readLog(progress.log).attempts.map((attempt) => exportedAttempt(attempt, input.optionText ?? NO_OPTION_TEXTS)),
    survey: input.survey,
    conceptTest: conceptTestExport(input.conceptTest ?? null),
  };
}

function exportedAttempt(attempt: TaskAttempt, optionText: OptionText): ExportedAttempt {
  const choice = attempt.quizChoice;
  return {
    ...attempt,
    hintsOpened: hintsOpened(attempt),
    quizChoiceId: choice === null ? null : optionId(choice),
    quizChoiceText: choice === null ? null : optionText(attempt.level, attempt.task, choice),
  };
}

/** The file's text: indented, so that it can be read in any editor. */
export function exportJson(input: ExportInput): string {
  return `${JSON.stringify(buildExport(input), null, 2)}\n`;
}
