import type { ConceptForm } from './concept-bank-schema.ts';

/**
 * Which form a learner takes before the levels and which after (issue 40). With one order
 * for everyone (A before, B after) a difference between the forms' difficulty looks like
 * learning; counterbalancing gives half of the learners B first, so that it averages out over
 * a class (the usual design of a pre/post test with parallel forms).
 */

export const CONCEPT_TEST_ORDERS = ['a-then-b', 'counterbalanced'] as const;
export type ConceptTestOrder = (typeof CONCEPT_TEST_ORDERS)[number];

export type ConceptPhase = 'pre' | 'post';

/** FNV-1a, 32 bits: the same attempt id always gives the same half. */
function hash(text: string): number {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193);
  }
  return h >>> 0;
}

/**
 * The forms of one playthrough: chosen by a stable hash of its attempt id, so that a reload
 * or a second tab gives the same forms, and a new attempt ("start again") may get the other
 * half.
 */
export function conceptForms(order: ConceptTestOrder, attemptId: string): Record<ConceptPhase, ConceptForm> {
  const bFirst = order === 'counterbalanced' && hash(attemptId) % 2 === 1;
  return bFirst ? { pre: 'B', post: 'A' } : { pre: 'A', post: 'B' };
}
