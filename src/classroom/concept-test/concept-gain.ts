import type { ConceptBank } from './concept-bank-schema.ts';
import type { ConceptTestAnswers, ConceptTestSubmission } from './concept-answers.ts';

/**
 * The concept test's result on the dashboard: per class and per concept, the average score
 * before and after and Hake's normalized gain
 *
 *   ⟨g⟩ = (%⟨post⟩ − %⟨pre⟩) / (100 % − %⟨pre⟩)
 *
 * (R. R. Hake, "Interactive-engagement versus traditional methods: a six-thousand-student
 * survey of mechanics test data for introductory physics courses", Am. J. Phys. 66 (1998)
 * 64–74): the gain of the class averages, as Hake defines it, not the average of each
 * learner's gain (which is undefined for a learner with a perfect pre-test). Both averages
 * are over the same learners, those who took both tests (n), so that a learner who left
 * early does not change the "before" of the class without being in its "after".
 *
 * A learner's score on a concept is the share of the items of that concept in the form they
 * took that they answered right (an item left open counts as wrong); the whole test's row
 * is the share of all the form's items.
 */

export interface GainRow {
  /** The concept's id, or null for the whole test. */
  concept: string | null;
  /** Learners with both tests (and items of this concept in both forms they took). */
  n: number;
  /** Average score before and after, as fractions 0–1 (null when n = 0). */
  pre: number | null;
  post: number | null;
  /** Hake's ⟨g⟩ of the class averages; null when n = 0 or the average before was 100 %. */
  gain: number | null;
}

export interface ClassGain {
  /** The class code, '' for learners without one. */
  classCode: string;
  rows: GainRow[];
  /** Learners with only the test before (they left before the end, or did not hand in the last file) and only the test after. */
  preOnly: number;
  postOnly: number;
}

export interface GainLearner {
  classCode: string;
  conceptTest?: ConceptTestAnswers | null;
}

/** The share right of the items of `concept` (null: all) in the learner's form, or null when that form has none. */
export function conceptScore(bank: ConceptBank, submission: ConceptTestSubmission, concept: string | null): number | null {
  const items = bank.items.filter((item) => item.form === submission.form && (concept === null || item.concept === concept));
  if (items.length === 0) return null;
  return items.filter((item) => submission.answers[item.id] === item.answer).length / items.length;
}

/** Hake's ⟨g⟩ from the two class averages (fractions 0–1); null when nothing was left to gain. */
export function normalizedGain(pre: number, post: number): number | null {
  return pre >= 1 ? null : (post - pre) / (1 - pre);
}

const mean = (values: readonly number[]) => values.reduce((sum, value) => sum + value, 0) / values.length;

function gainRow(bank: ConceptBank, both: readonly { pre: ConceptTestSubmission; post: ConceptTestSubmission }[], concept: string | null): GainRow {
  const pairs = both.flatMap(({ pre, post }) => {
    const before = conceptScore(bank, pre, concept);
    const after = conceptScore(bank, post, concept);
    return before === null || after === null ? [] : [{ before, after }];
  });
  if (pairs.length === 0) return { concept, n: 0, pre: null, post: null, gain: null };
  const pre = mean(pairs.map((pair) => pair.before));
  const post = mean(pairs.map((pair) => pair.after));
  return { concept, n: pairs.length, pre, post, gain: normalizedGain(pre, post) };
}

/** Per class code (sorted, '' first), the whole test's row and one row per concept of the bank. */
export function conceptGains(learners: readonly GainLearner[], bank: ConceptBank): ClassGain[] {
  const tested = learners.filter((learner) => learner.conceptTest?.pre || learner.conceptTest?.post);
  const classes = [...new Set(tested.map((learner) => learner.classCode))].sort((a, b) => a.localeCompare(b, 'en', { numeric: true }));
  return classes.map((classCode) => {
    const inClass = tested.filter((learner) => learner.classCode === classCode);
    const both = inClass.flatMap(({ conceptTest }) => (conceptTest?.pre && conceptTest.post ? [{ pre: conceptTest.pre, post: conceptTest.post }] : []));
    return {
      classCode,
      rows: [null, ...bank.concepts.map((concept) => concept.id)].map((concept) => gainRow(bank, both, concept)),
      preOnly: inClass.filter(({ conceptTest }) => conceptTest?.pre && !conceptTest.post).length,
      postOnly: inClass.filter(({ conceptTest }) => !conceptTest?.pre && conceptTest?.post).length,
    };
  });
}
