import { LAB_CODE_KEY_PREFIX as PREFIX } from '../../../quest/progress-lab-code.ts';

/**
 * The learner's code per lab, kept in this browser so that it survives a reload. A key of
 * its own beside the progress (`rtq.progress`); the progress file carries it (progress-lab-code.ts).
 */

export function savedCode(lab: string): string | null {
  try {
    return localStorage.getItem(PREFIX + lab);
  } catch {
    return null;
  }
}

export function saveCode(lab: string, code: string | null): void {
  try {
    if (code === null) localStorage.removeItem(PREFIX + lab);
    else localStorage.setItem(PREFIX + lab, code);
  } catch {
    // Storage full or refused (a private window): the code stays in the editor for this visit.
  }
}
