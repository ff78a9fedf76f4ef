import { z } from 'zod';
import { kebabId } from './kebab-id.ts';
import type { KeyValueStorage } from './saved-backups.ts';

/**
 * The learner's code of each code lab, in the progress file. In the browser each lab's code
 * is kept under a key of its own (`rtq.code-lab.<lab>`, code-drafts.ts), beside the progress;
 * an export gathers it into the file's `code` and an import puts it back under those keys.
 * Saved progress (`rtq.progress`) never holds it, so that it is kept in one place only.
 */

/** Where a lab's code is kept in this browser: this prefix, then the lab's name. */
export const LAB_CODE_KEY_PREFIX = 'rtq.code-lab.';

/**
 * The most characters of one lab's code in a progress file: the labs' functions are a few
 * dozen lines, so a longer text is not the learner's code (a file edited by hand, or damaged).
 */
export const LAB_CODE_MAX = 20_000;

/**
 * The file's `code`: lab name → the learner's code. Optional, so that files from before it
 * (and files of a learner who wrote no code) read as they did; an entry that is not text or
 * is too long is left out alone when the file is read (progress-salvage.ts).
 */
export const labCodeSchema = z.record(kebabId(), z.string().max(LAB_CODE_MAX)).optional();

export type LabCode = Record<string, string>;

/**
 * Of an imported file's code, the labs whose code was refused (not text, too long; '' when
 * the file's `code` was refused whole) and those whose code this browser's storage did not
 * take: their code here stays as it was.
 */
export type CodeNotImported = { refused: string[]; notSaved: string[] };

/** The code kept in `storage` for every lab (none when there is none, or when storage cannot be read). */
export function keptLabCode(storage: KeyValueStorage): LabCode {
  const code: LabCode = {};
  try {
    for (let index = 0; index < storage.length; index++) {
      const key = storage.key(index);
      if (key === null || !key.startsWith(LAB_CODE_KEY_PREFIX)) continue;
      const text = storage.getItem(key);
      if (text !== null) code[key.slice(LAB_CODE_KEY_PREFIX.length)] = text;
    }
  } catch {
    // Storage that cannot be read: the file goes without code rather than not at all.
  }
  return code;
}

/**
 * Keeps each lab's code of an imported file in `storage`, replacing that lab's code there;
 * a lab the file has no code for keeps the code it had. Returns the labs whose code could
 * not be written (storage full or refused).
 */
export function keepLabCode(storage: KeyValueStorage, code: LabCode): string[] {
  const notKept: string[] = [];
  for (const [lab, text] of Object.entries(code)) {
    try {
      storage.setItem(LAB_CODE_KEY_PREFIX + lab, text);
    } catch {
      notKept.push(lab);
    }
  }
  return notKept;
}
