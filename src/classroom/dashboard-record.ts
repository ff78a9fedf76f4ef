import type { Issue } from '../util/issue.ts';
import type { HandedInSurvey } from './survey-columns.ts';
import type { ConceptTestAnswers } from './concept-test/concept-answers.ts';
import type { LevelVisit, TaskAttempt } from './task-attempts.ts';

/**
 * One learner's export as the dashboard counts it, whatever file it came from (a JSON
 * export carries everything; a CSV export only the task attempts).
 */
export interface ClassRecord {
  /** The file it was read from (shown when something about it needs explaining). */
  file: string;
  /** The participant code, or '' when none was asked. */
  participant: string;
  /**
   * Who and which playthrough (learner-identity.ts). Files from before exports carried them
   * get stand-ins: the participant code (else the file) as learner, the log's start time
   * (else the file) as attempt, so that old files still count once each.
   */
  learnerId: string;
  attemptId: string;
  /** '' when the file does not say. */
  installId: string;
  /** The assignment's title and id, or '' for free play. */
  assignment: string;
  assignmentId: string;
  /** The assignment's class code, or ''. */
  classCode: string;
  /** The version of the app that wrote the file, or '' when the file does not say. */
  appVersion: string;
  /** The device's minutes ahead of UTC when the file was made, or '' when the file does not say. */
  utcOffsetMin: string;
  attempts: TaskAttempt[];
  /** Level visits; empty for a CSV export, which has no level events. */
  visits: LevelVisit[];
  /** The closing survey's answers (and which questions were asked), or null when the learner did not hand one in. */
  survey: HandedInSurvey | null;
  /** The concept test's answers, or null (or absent) when the learner took none. */
  conceptTest?: ConceptTestAnswers | null;
}

/** A file that was not counted, and why. */
export interface SkippedFile {
  file: string;
  /** Why, in the app's language. */
  reason: string;
  /**
   * The schema's or the JSON reader's own issue (src/util/issue.ts): the page says it in its
   * language after `reason`.
   */
  detail?: Issue;
}

export type FileRead = { ok: true; record: ClassRecord } | ({ ok: false } & SkippedFile);
