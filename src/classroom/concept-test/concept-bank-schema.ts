import { z } from 'zod';
import { describeIssue, formatIssues } from '../../scene/scene-issues.ts';
import { kebabId } from '../../quest/kebab-id.ts';
import { localizedTextSchema } from '../../quest/localized-text.ts';
import { listOf } from '../../scene/scene-schema-parts.ts';

/**
 * The concept test's item bank (issue 40, "learning measured"): multiple-choice questions on
 * the core ideas, each written from a wrong answer pupils really give, in two parallel forms
 * so the test before the levels and the one after are not the same questions (form A before
 * and B after, or counterbalanced). An item of form A and its twin of form B share a `pair`
 * and a concept: the pre/post gain per concept (Hake 1998, ⟨g⟩ = (post − pre)/(100 % − pre))
 * compares like with like.
 */

const CHOICES = [3, 5] as const;

const choiceSchema = z.strictObject({
  /** Stable across languages and shuffles: the exports' `quiz_choice`, the codebook's row. */
  id: kebabId(),
  text: localizedTextSchema,
  /** For a wrong choice: the wrong idea it stands for, in the codebook and the dashboard. */
  misconception: localizedTextSchema.optional(),
});

const itemSchema = z.strictObject({
  id: kebabId(),
  concept: kebabId(),
  form: z.enum(['A', 'B']),
  /** The id both forms' items on the same question share. */
  pair: kebabId(),
  question: localizedTextSchema,
  choices: listOf(choiceSchema, [...CHOICES]),
  /** The id of the right choice. */
  answer: kebabId(),
});

export const conceptBankSchema = z
  .strictObject({
    version: z.literal(1),
    concepts: listOf(z.strictObject({ id: kebabId(), name: localizedTextSchema }), [1, 40]),
    items: listOf(itemSchema, [2, 400]),
  })
  .superRefine((bank, context) => {
    const concepts = new Set(bank.concepts.map((concept) => concept.id));
    const ids = new Set<string>();
    const pairs = new Map<string, { concept: string; forms: string[] }>();
    bank.items.forEach((item, index) => {
      const at = (...path: (string | number)[]) => ['items', index, ...path];
      if (ids.has(item.id)) context.addIssue({ code: 'custom', path: at('id'), input: item.id, message: `"${item.id}" is used more than once` });
      ids.add(item.id);
      if (!concepts.has(item.concept))
        context.addIssue({ code: 'custom', path: at('concept'), input: item.concept, message: `"${item.concept}" is no concept of the bank` });
      if (!item.choices.some((choice) => choice.id === item.answer))
        context.addIssue({ code: 'custom', path: at('answer'), input: item.answer, message: `"${item.answer}" is none of the item's choices` });
      if (new Set(item.choices.map((choice) => choice.id)).size !== item.choices.length)
        context.addIssue({ code: 'custom', path: at('choices'), input: item.choices, message: 'choice ids must differ' });
      const pair = pairs.get(item.pair) ?? { concept: item.concept, forms: [] };
      if (pair.concept !== item.concept)
        context.addIssue({ code: 'custom', path: at('concept'), input: item.concept, message: `pair "${item.pair}" spans two concepts` });
      pair.forms.push(item.form);
      pairs.set(item.pair, pair);
    });
    for (const [pair, { forms }] of pairs) {
      if (forms.length !== 2 || !forms.includes('A') || !forms.includes('B'))
        context.addIssue({ code: 'custom', path: ['items'], input: pair, message: `pair "${pair}" needs one item of form A and one of form B` });
    }
  });

export type ConceptBank = z.output<typeof conceptBankSchema>;
export type ConceptItem = ConceptBank['items'][number];
export type ConceptForm = ConceptItem['form'];

export type ConceptBankParseResult = { ok: true; bank: ConceptBank } | { ok: false; errors: string[] };

export function parseConceptBank(input: unknown): ConceptBankParseResult {
  const result = conceptBankSchema.safeParse(input, { error: describeIssue });
  return result.success ? { ok: true, bank: result.data } : { ok: false, errors: formatIssues(result.error.issues) };
}
