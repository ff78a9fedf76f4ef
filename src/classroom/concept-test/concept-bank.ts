import { parseConceptBank, type ConceptBank, type ConceptForm, type ConceptItem } from './concept-bank-schema.ts';

/**
 * The concept test's item bank as the app ships it (concept-bank.json, checked by
 * concept-bank-schema.ts). A bank that does not parse offers no test: the teacher page then
 * has no concept test to choose, and an assignment that asks for one plays without it
 * (tests/classroom/concept-test.test.ts keeps the file valid).
 *
 * Loaded only where a concept test is used (an assignment that asks for one, the teacher
 * page, the dashboard): its 44 items in two languages would be a tenth of the first load.
 */
let bank: ConceptBank | null = null;
let loading: Promise<ConceptBank | null> | null = null;

/** The bank, once loadConceptBank has resolved; null before, or when it does not parse. */
export function conceptBankNow(): ConceptBank | null {
  return bank;
}

/** Loads the bank (once); resolves to it, or null when it does not parse. */
export function loadConceptBank(): Promise<ConceptBank | null> {
  loading ??= import('./concept-bank.json').then(({ default: file }) => {
    const parsed = parseConceptBank(file);
    bank = parsed.ok ? parsed.bank : null;
    return bank;
  });
  return loading;
}

/** The items of one form, in the bank's order: the test as a learner takes it. */
export function formItems(bank: ConceptBank, form: ConceptForm): ConceptItem[] {
  return bank.items.filter((item) => item.form === form);
}
