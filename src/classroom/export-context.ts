import { version } from '../../package.json';
import type { Progress } from '../quest/progress.ts';
import type { Assignment } from './assignment.ts';
import { assignmentId } from './assignment-id.ts';
import type { AttemptOwner } from './attempt-columns.ts';
import { learnerId } from './learner-identity.ts';
import type { OptionText } from './quiz-options.ts';
import type { SurveySubmission } from './survey-answers.ts';
import type { ConceptTestAnswers } from './concept-test/concept-answers.ts';

/**
 * Everything an export is made from (export-csv.ts, export-json.ts, export-xapi.ts): the
 * learner's progress with its event log, and the classroom session around it.
 */
export interface ExportInput {
  progress: Progress;
  /** The code the learner typed at the start, or null when none was asked. */
  participant: string | null;
  /** This browser's random id (learner-identity.ts), or '' when the learner has a participant code. */
  installId: string;
  /** This playthrough's random id: the same in every file exported from one progress. */
  attemptId: string;
  /** The teacher's assignment, or null in free play. */
  assignment: Assignment | null;
  survey: SurveySubmission | null;
  /** The concept test's answers, when the assignment has one. */
  conceptTest?: ConceptTestAnswers | null;
  /** ISO 8601; the moment of the download. */
  exportedAt: string;
  /** The app's version (package.json), so that a researcher knows which game produced the data. */
  appVersion: string;
  /**
   * Minutes the device's clock is ahead of UTC at the download (`-new Date().getTimezoneOffset()`:
   * 60 in Dutch winter time, 120 in summer), so that UTC times can be read as the pupil's
   * clock showed them; absent when unknown.
   */
  utcOffsetMin?: number;
  /** The texts of quiz options in the export's language (quiz-options.ts); without it the text columns stay empty. */
  optionText?: OptionText;
}

/** The app's version, from package.json (vite and Node both import JSON). */
export const APP_VERSION: string = version;

/** The assignment as exports name it: its id and title, or nulls in free play. */
export function assignmentLabel(assignment: Assignment | null): { id: string | null; title: string | null } {
  return assignment ? { id: assignmentId(assignment), title: assignment.title } : { id: null, title: null };
}

/** The learner and playthrough the export's rows belong to. */
export function exportOwner(input: ExportInput): AttemptOwner {
  const { id, title } = assignmentLabel(input.assignment);
  return {
    learnerId: learnerId(input.participant, input.installId),
    attemptId: input.attemptId,
    installId: input.installId,
    participant: input.participant ?? '',
    assignment: title ?? '',
    assignmentId: id ?? '',
    classCode: input.assignment?.classCode ?? '',
    appVersion: input.appVersion,
    utcOffsetMin: input.utcOffsetMin === undefined ? '' : String(input.utcOffsetMin),
    survey: input.survey && { id: input.survey.survey, answers: input.survey.answers },
    conceptTest: input.conceptTest ?? null,
  };
}
