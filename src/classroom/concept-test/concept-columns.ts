import type { AttemptColumn } from '../attempt-columns.ts';
import { rightCount, type ConceptTestAnswers, type ConceptTestSubmission } from './concept-answers.ts';
import { conceptBankNow } from './concept-bank.ts';
import type { ConceptPhase } from './concept-test-plan.ts';

/**
 * The concept test's columns in the CSV export (after the table in attempt-columns.ts, before
 * the survey's): per phase the form taken, how many answers were right, and the answers as
 * `item=choice` pairs (ids never hold a space or `=`), the same on each of a learner's rows
 * like the survey's. Empty when the test was not taken. The JSON export has the same answers
 * one per row with concept and right (concept-answers.ts conceptAnswerRows).
 */

function submissionOf(owner: { conceptTest?: ConceptTestAnswers | null }, phase: ConceptPhase): ConceptTestSubmission | null {
  return owner.conceptTest?.[phase] ?? null;
}

function phaseColumns(phase: ConceptPhase): AttemptColumn[] {
  const plain = { quoted: false, required: false };
  return [
    {
      name: `concept_${phase}_form`,
      ...plain,
      value: ({ owner }) => submissionOf(owner, phase)?.form ?? '',
      read: (cell, into) => {
        if (cell !== 'A' && cell !== 'B') return;
        into.owner.conceptTest = { ...into.owner.conceptTest, [phase]: { form: cell, submittedAt: '', answers: {} } };
      },
    },
    {
      name: `concept_${phase}_right`,
      ...plain,
      value: ({ owner }) => {
        const submission = submissionOf(owner, phase);
        return submission ? rightCount(conceptBankNow(), submission) : '';
      },
    },
    {
      name: `concept_${phase}_answers`,
      ...plain,
      value: ({ owner }) =>
        Object.entries(submissionOf(owner, phase)?.answers ?? {})
          .map(([item, choice]) => `${item}=${choice}`)
          .join(' '),
      read: (cell, into) => {
        const submission = into.owner.conceptTest[phase];
        if (!submission) return;
        for (const pair of cell.split(' ')) {
          const [item, choice] = pair.split('=');
          if (item && choice) submission.answers[item] = choice;
        }
      },
    },
  ];
}

export const CONCEPT_COLUMNS: readonly AttemptColumn[] = [...phaseColumns('pre'), ...phaseColumns('post')];
