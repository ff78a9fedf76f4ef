import type { Assignment } from '../classroom/assignment.ts';
import type { ConceptTestAnswers } from '../classroom/concept-test/concept-answers.ts';
import { conceptBankNow } from '../classroom/concept-test/concept-bank.ts';
import type { ConceptPhase } from '../classroom/concept-test/concept-test-plan.ts';

/**
 * Which concept test the learner is to take now, if any (issue 40): the one before, while
 * nothing of the assignment has been played yet (after the participant code, before the first
 * level: the game waits for it, as for the code); the one after, once every level is passed
 * (before the closing survey). A learner who had started before the test was there (or whose
 * test before was lost) is not asked for it midway: a "before" taken halfway measures nothing.
 */
export function conceptTestDue(
  assignment: Assignment | null,
  answers: ConceptTestAnswers,
  progress: { played: boolean; allPassed: boolean },
): ConceptPhase | null {
  if (!assignment?.conceptTest || !conceptBankNow()) return null;
  if (!answers.pre && !answers.post && !progress.played) return 'pre';
  if (!answers.post && progress.allPassed) return 'post';
  return null;
}
