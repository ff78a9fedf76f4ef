import type { Issue } from '../util/issue.ts';
import { localIssue } from './local-reason.ts';

/**
 * Why a scene file, a level, a link or saved progress cannot be used, in the app's language.
 * An issue with a coded reason (src/util/issue.ts) is said by its code's msg()
 * (local-reason.ts). Reasons not coded yet come as English text (the level rules, goals,
 * progress and assignment checks, which `rt validate` prints as they are): the app reads
 * each by its English pattern and says it again through msg() (issue-translation.ts and the
 * pattern lists it gathers). Those patterns load after a translation of the app (locale.ts),
 * not with the first screen: until they have, and always in English, such a reason is shown
 * as it was written.
 */

interface Translation {
  line: (line: string) => string;
  reason: (reason: string) => string;
}

let translate: Translation | null = null;

/** The window event sent once the patterns have loaded, so a reason on screen is said again. */
export const ISSUE_TEXTS_LOADED = 'rt-issue-texts-loaded';

/** Loads the patterns; asked for once a language other than English is in use. */
export async function loadIssueTranslation(): Promise<void> {
  if (translate) return;
  const { translateIssue, reasonText } = await import('./issue-translation.ts');
  translate = { line: translateIssue, reason: reasonText };
}

/** A reason not coded yet, in the app's language when a pattern knows it. */
function wordedText(text: string): string {
  return translate ? translate.reason(text) : text;
}

/** One issue, or one `path: reason` line (or a bare reason) not coded yet, in the app's language. */
export function issueText(issue: Issue | string): string {
  if (typeof issue !== 'string') return localIssue(issue, wordedText);
  return translate ? translate.line(issue) : issue;
}

/** Every line of a multi-line reason (a store's refusal may hold several) in the app's language. */
export function issueLines(text: string): string {
  return text.split('\n').map(issueText).join('\n');
}
