import type { ClassRecord } from '../dashboard-record.ts';
import type { ConceptTestAnswers } from './concept-answers.ts';

/**
 * One learner's concept test from several files (dashboard-learners.ts): a copy exported
 * before the test after the levels still has the one before, so each phase is taken from the
 * files that have it: the test before from the first (in the order given: the playthroughs in
 * the order they were played), the test after from the last. Null when no file has either.
 */
export function joinedConceptTests(records: readonly ClassRecord[]): ConceptTestAnswers | null {
  const pre = records.find((record) => record.conceptTest?.pre)?.conceptTest?.pre ?? null;
  const post = [...records].reverse().find((record) => record.conceptTest?.post)?.conceptTest?.post ?? null;
  return pre || post ? { pre, post } : null;
}
