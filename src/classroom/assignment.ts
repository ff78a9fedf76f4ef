import type { ConceptTestOrder } from './concept-test/concept-test-plan.ts';

/**
 * A teacher's assignment (spec/classroom.md): which levels, in which order, what is required,
 * and how the session starts and ends. Encoded in a link (see assignment-link.ts); the game
 * reads it to limit the level map, to ask for a participant code and to show the survey.
 */
export interface Assignment {
  version: 1;
  /** Shown to the students, e.g. "Ray tracing, lesson 2". */
  title: string;
  /** Level ids in the order the students play them. */
  levels: string[];
  /** Per level id: the task ids a student must finish (default: the level's mandatory tasks). */
  requiredTasks: Record<string, string[]>;
  /** Levels outside the assignment: hidden from the map, or shown (playable after it). */
  otherLevels: 'hidden' | 'shown';
  locale: 'en' | 'nl';
  /** Ask for a participant code at the start (research studies). */
  askParticipantCode: boolean;
  /** The closing survey's id (a data file in src/classroom/surveys), or null for none. */
  survey: string | null;
  /** The class the link is for ("3B"): lets the dashboard show one class of several with the same lesson. */
  classCode?: string;
  /** The school's own address for xAPI accounts (actor.account.homePage), so that code "P-07" of two schools are two people. */
  xapiHomePage?: string;
  /**
   * The information pupils read before they type their participant code and start
   * (consent-text.ts); absent: the app's default text, in the pupil's language.
   */
  consent?: string;
  /** A concept test before the first level and after the last (concept-test-plan.ts); absent: none. */
  conceptTest?: ConceptTestOrder;
  /**
   * The teacher's own choice of the survey's questions (survey-for-levels.ts): per question
   * id, asked (true) or not (false), where it differs from the default, which asks the
   * questions that fit the levels; absent: the default.
   */
  surveyQuestions?: Record<string, boolean>;
}
