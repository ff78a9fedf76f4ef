import { codeKey } from './dashboard-class-list.ts';
import type { ClassRecord } from './dashboard-record.ts';
import { joinedConceptTests } from './concept-test/concept-test-join.ts';

/**
 * One learner is one learner: a student who pressed every download button, or handed in a
 * file midway and another at the end, counts once.
 *
 * Files of one playthrough (the same attempt id) are copies of one growing log taken at
 * different moments: the most complete one is kept and the others are not counted at all
 * (never added up). A log only grows, so "most complete" is the one with the most finished
 * task attempts, then the most attempts, then the latest moment; on a tie a JSON export
 * (which also has the level visits) beats a CSV export. A learner's playthroughs (the same
 * learner id in the same assignment, whatever its case: say, after "start again") are then joined, in the
 * order they were played, so the learner is counted once with all their attempts.
 */
export interface ClassLearner extends ClassRecord {
  /** The kept file of each playthrough, in the order they were played. */
  parts: ClassRecord[];
  /** Every file that was read for this learner, kept or not. */
  files: string[];
}

const lastMoment = (record: ClassRecord) => Math.max(0, ...record.attempts.map((attempt) => Date.parse(attempt.startedAt) + attempt.durationMs));
const firstMoment = (record: ClassRecord) => Math.min(Number.POSITIVE_INFINITY, ...record.attempts.map((attempt) => Date.parse(attempt.startedAt)));

/** How complete a copy of a log is, compared from the first number on. */
function completeness(record: ClassRecord): number[] {
  return [
    record.attempts.filter((attempt) => attempt.how !== null).length,
    record.attempts.length,
    lastMoment(record),
    record.visits.length,
    record.survey ? 1 : 0,
  ];
}

function moreComplete(a: ClassRecord, b: ClassRecord): ClassRecord {
  const [left, right] = [completeness(a), completeness(b)];
  const differs = left.findIndex((value, index) => value !== right[index]);
  return differs >= 0 && right[differs] > left[differs] ? b : a;
}

function groupBy<Item>(items: readonly Item[], key: (item: Item) => string): Item[][] {
  const groups = new Map<string, Item[]>();
  for (const item of items) groups.set(key(item), [...(groups.get(key(item)) ?? []), item]);
  return [...groups.values()];
}

/** The class's learners from the records of every file read, each counted once. */
export function classLearners(records: readonly ClassRecord[]): ClassLearner[] {
  const playthroughs = groupBy(records, (record) => `${record.assignmentId}\u0000${record.attemptId}`).map((copies) => {
    const kept = copies.reduce(moreComplete);
    // A copy taken before the survey was answered does not lose the answers of another.
    const survey =
      kept.survey ??
      copies.filter((copy) => copy.survey).reduce<ClassRecord | null>((best, copy) => (best ? moreComplete(best, copy) : copy), null)?.survey ??
      null;
    return { kept: { ...kept, survey, conceptTest: joinedConceptTests(copies) }, files: copies.map((copy) => copy.file) };
  });
  // Codes are typed by pupils: "5h2-03" and "5H2-03" are one learner.
  return groupBy(playthroughs, ({ kept }) => `${kept.assignmentId}\u0000${codeKey(kept.learnerId)}`).map((group) => {
    const parts = group.map(({ kept }) => kept).sort((a, b) => firstMoment(a) - firstMoment(b));
    const latest = parts.at(-1)!;
    return {
      ...latest,
      attempts: parts.flatMap((part) => part.attempts),
      visits: parts.flatMap((part) => part.visits),
      survey: [...parts].reverse().find((part) => part.survey)?.survey ?? null,
      conceptTest: joinedConceptTests(parts),
      parts,
      files: group.flatMap(({ files }) => files),
    };
  });
}

/** What to show: one assignment ('' for free play, null for all) and one class code (null for all). */
export interface LearnerFilter {
  assignmentId: string | null;
  classCode: string | null;
}

export function filterLearners(learners: readonly ClassLearner[], filter: LearnerFilter): ClassLearner[] {
  return learners.filter(
    (learner) =>
      (filter.assignmentId === null || learner.assignmentId === filter.assignmentId) && (filter.classCode === null || learner.classCode === filter.classCode),
  );
}

/** The assignments among the learners (id and title, '' for free play), with how many learners each. */
export function assignmentsOf(learners: readonly ClassLearner[]): { id: string; title: string; learners: number }[] {
  return groupBy(learners, (learner) => learner.assignmentId).map((group) => ({
    id: group[0].assignmentId,
    title: group[0].assignment,
    learners: group.length,
  }));
}

/** The class codes among the learners ('' for none), sorted. */
export function classCodesOf(learners: readonly ClassLearner[]): string[] {
  return [...new Set(learners.map((learner) => learner.classCode))].sort((a, b) => a.localeCompare(b, 'en', { numeric: true }));
}
