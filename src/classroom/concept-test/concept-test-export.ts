import { conceptAnswerRows, type ConceptAnswerRow, type ConceptTestAnswers } from './concept-answers.ts';
import { conceptBankNow } from './concept-bank.ts';

/**
 * The concept test in the JSON export: each phase as it was saved (form, time, item → choice,
 * which the dashboard reads back), and every answer as a row with its concept, form, phase
 * and whether it was right, for a researcher who wants a long table without the bank.
 */
export type ConceptTestExport = ConceptTestAnswers & { answers: ConceptAnswerRow[] };

export function conceptTestExport(answers: ConceptTestAnswers | null): ConceptTestExport | null {
  if (!answers || (!answers.pre && !answers.post)) return null;
  return { ...answers, answers: conceptAnswerRows(conceptBankNow(), answers) };
}
