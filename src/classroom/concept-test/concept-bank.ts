import bankFile from './concept-bank.json';
import { parseConceptBank, type ConceptBank, type ConceptForm, type ConceptItem } from './concept-bank-schema.ts';

/**
 * The concept test's item bank as the app ships it (concept-bank.json, checked by
 * concept-bank-schema.ts). A bank that does not parse offers no test: the teacher page then
 * has no concept test to choose, and an assignment that asks for one plays without it
 * (tests/classroom/concept-test.test.ts keeps the file valid).
 */
const parsed = parseConceptBank(bankFile);

export const conceptBank: ConceptBank | null = parsed.ok ? parsed.bank : null;

/** The items of one form, in the bank's order: the test as a learner takes it. */
export function formItems(bank: ConceptBank, form: ConceptForm): ConceptItem[] {
  return bank.items.filter((item) => item.form === form);
}
