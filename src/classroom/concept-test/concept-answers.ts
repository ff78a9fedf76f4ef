import type { ConceptBank, ConceptForm } from './concept-bank-schema.ts';
import type { ConceptPhase } from './concept-test-plan.ts';

/**
 * A learner's answers to the concept test, as saved (concept-test-store.ts) and exported:
 * per phase the form taken and, per item id, the id of the choice picked. Ids, not
 * positions: the choices are shown shuffled (choice-order.ts), and an id means the same in
 * both languages.
 */
export interface ConceptTestSubmission {
  form: ConceptForm;
  /** ISO 8601. */
  submittedAt: string;
  /** Item id → choice id. */
  answers: Record<string, string>;
}

export type ConceptTestAnswers = Record<ConceptPhase, ConceptTestSubmission | null>;

export const NO_CONCEPT_ANSWERS: ConceptTestAnswers = { pre: null, post: null };

/** One answer in the long form the JSON export and a researcher's table use. */
export interface ConceptAnswerRow {
  item: string;
  concept: string;
  form: ConceptForm;
  phase: ConceptPhase;
  choice: string;
  /** Null when the bank of this version has no such item (an export of another version). */
  right: boolean | null;
}

/** Whether `choice` is the answer of item `itemId`; null for an item the bank does not have. */
export function isRight(bank: ConceptBank | null, itemId: string, choice: string): boolean | null {
  const item = bank?.items.find((candidate) => candidate.id === itemId);
  return item ? item.answer === choice : null;
}

/** Every answer of both phases as rows, pre first, each in the order it was saved. */
export function conceptAnswerRows(bank: ConceptBank | null, answers: ConceptTestAnswers): ConceptAnswerRow[] {
  return (['pre', 'post'] as const).flatMap((phase) => {
    const submission = answers[phase];
    if (!submission) return [];
    return Object.entries(submission.answers).map(([item, choice]) => ({
      item,
      concept: bank?.items.find((candidate) => candidate.id === item)?.concept ?? '',
      form: submission.form,
      phase,
      choice,
      right: isRight(bank, item, choice),
    }));
  });
}

/** How many of a submission's answers are right (items the bank lacks count as not right). */
export function rightCount(bank: ConceptBank | null, submission: ConceptTestSubmission): number {
  return Object.entries(submission.answers).filter(([item, choice]) => isRight(bank, item, choice) === true).length;
}
