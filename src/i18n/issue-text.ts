/**
 * The `path: reason` lines that say why a scene file, a level, a link or saved progress
 * cannot be used, in the app's language. The schemas, the level rules and the JSON reader
 * are pure (no lit; `rt validate` prints them as they are) and word their reasons in
 * English; the learner-facing app reads each reason by its English pattern and says it
 * again through msg() (issue-translation.ts and the pattern lists it gathers). Those
 * patterns load after a translation of the app (locale.ts), not with the first screen: until
 * they have, and always in English, a line is shown as the schema wrote it.
 */

let translate: ((line: string) => string) | null = null;

/** Loads the patterns; asked for once a language other than English is in use. */
export async function loadIssueTranslation(): Promise<void> {
  translate ??= (await import('./issue-translation.ts')).translateIssue;
}

/** One `path: reason` line (or a bare reason) in the app's language. */
export function issueText(line: string): string {
  return translate ? translate(line) : line;
}

/** Every line of a multi-line reason (a store's refusal may hold several) in the app's language. */
export function issueLines(text: string): string {
  return text.split('\n').map(issueText).join('\n');
}
