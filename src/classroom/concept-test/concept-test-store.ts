import { writeBackup, type KeyValueStorage } from '../../quest/saved-backups.ts';
import { isRecord } from '../../util/is-record.ts';
import { readJson } from '../../util/read-json.ts';
import { NO_CONCEPT_ANSWERS, type ConceptTestAnswers, type ConceptTestSubmission } from './concept-answers.ts';

/**
 * A learner's concept-test answers, kept next to their progress under its key plus
 * `.concept-test`, as the survey's answers are (survey-store.ts): apart per assignment, read
 * again after a reload, written by the quest session through its pending writes (so answers
 * that storage refuses stay in memory and are written at the next save).
 *
 * A damaged record is not passed over in silence: what can still be read (each phase, each
 * answer) is kept, what cannot is named, and the exact text is backed up (saved-backups.ts)
 * before anything is written over it.
 */

export function conceptTestKey(progressKey: string): string {
  return `${progressKey}.concept-test`;
}

export interface ConceptTestDamage {
  /** `pre`, `post`, or `pre.<item id>` for one answer; `record` when the text was no JSON. */
  lost: string[];
  raw: string;
  /** Where it was backed up, or null when there was no room (then it must not be written over). */
  backupKey: string | null;
}

export type LoadedConceptTest = { answers: ConceptTestAnswers; damage: ConceptTestDamage | null };

export function loadConceptTest(storage: KeyValueStorage, progressKey: string, wallMs: number): LoadedConceptTest {
  const key = conceptTestKey(progressKey);
  let raw: string | null;
  try {
    raw = storage.getItem(key);
  } catch {
    return { answers: NO_CONCEPT_ANSWERS, damage: null }; // the progress store reports storage that cannot be read
  }
  if (raw === null) return { answers: NO_CONCEPT_ANSWERS, damage: null };
  const read = readConceptTestText(raw);
  if (read.lost.length === 0) return { answers: read.answers, damage: null };
  return { answers: read.answers, damage: { lost: read.lost, raw, backupKey: writeBackup(storage, key, raw, wallMs) } };
}

/** What can be read of a saved record; fields this version does not know are ignored. */
export function readConceptTestText(raw: string): { answers: ConceptTestAnswers; lost: string[] } {
  const json = readJson(raw);
  return json.ok && isRecord(json.value) ? readConceptTestValue(json.value) : { answers: NO_CONCEPT_ANSWERS, lost: ['record'] };
}

/** The answers of a record as saved (or as the JSON export's `conceptTest` holds them). */
export function readConceptTestValue(record: Record<string, unknown>): { answers: ConceptTestAnswers; lost: string[] } {
  const lost: string[] = [];
  const phase = (name: 'pre' | 'post'): ConceptTestSubmission | null => {
    const value = record[name];
    if (value === null || value === undefined) return null;
    const form = isRecord(value) && (value.form === 'A' || value.form === 'B') ? value.form : null;
    const at = isRecord(value) && typeof value.submittedAt === 'string' ? value.submittedAt : null;
    if (!isRecord(value) || form === null || at === null || !isRecord(value.answers)) {
      lost.push(name);
      return null;
    }
    const answers: Record<string, string> = {};
    for (const [item, choice] of Object.entries(value.answers)) {
      if (typeof choice === 'string' && choice !== '') answers[item] = choice;
      else lost.push(`${name}.${item}`);
    }
    return { form, submittedAt: at, answers };
  };
  return { answers: { pre: phase('pre'), post: phase('post') }, lost };
}
