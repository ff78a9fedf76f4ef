import { issueLine, type Issue } from '../util/issue.ts';

/**
 * Why a scene file, a level, a link, saved progress or a change cannot be used, in the app's
 * language: each issue's coded reason (src/util/issue.ts) said by its code's msg()
 * (local-reason.ts). Those sayings load after a translation of the app (locale.ts), not with
 * the first screen, since a refusal is rare: until they have, and always in English, an issue
 * is shown in the English `rt validate` prints, which is the same words.
 */

let localIssue: ((issue: Issue) => string) | null = null;

/** Loads the sayings; asked for once a language other than English is in use. */
export async function loadIssueTranslation(): Promise<void> {
  localIssue ??= (await import('./local-reason.ts')).localIssue;
}

/** One issue in the app's language. */
export function issueText(issue: Issue): string {
  return localIssue ? localIssue(issue) : issueLine(issue);
}
