import { msg, str } from '@lit/localize';

/**
 * How a `path: reason` line is said again in the app's language (issue-text.ts): a list of
 * English patterns, each with what to say for a match. Shared here are the matching and
 * the parts many reasons quote: the value a field got and the kind of value it must be.
 */

/** A pattern and what to say for a match; null when, after all, it is not this rule's to say. */
export type Rule = readonly [RegExp, (...parts: string[]) => string | null];

/** What the first rule that matches all of `text` says, or null when none does. */
export function translatedOrNull(rules: readonly Rule[], text: string): string | null {
  for (const [pattern, say] of rules) {
    const match = pattern.exec(text);
    const said = match ? say(...match.slice(1)) : null;
    if (said !== null) return said;
  }
  return null;
}

/** `text` said by the first rule that knows it; `text` itself when none does. */
export function translated(rules: readonly Rule[], text: string): string {
  return translatedOrNull(rules, text) ?? text;
}

/** The values in "got …" (describeValue in scene-issues.ts); JSON literals and quoted text stay. */
const VALUES: readonly Rule[] = [
  [/^nothing$/, () => msg('nothing')],
  [/^a list of 1 item$/, () => msg('a list of 1 item')],
  [/^a list of (\d+) items$/, (count) => msg(str`a list of ${count} items`)],
  [/^an object$/, () => msg('an object')],
];

export const value = (text: string) => translated(VALUES, text);

/**
 * What a value must be (EXPECTED in scene-issues.ts, the list items of scene-schema-parts.ts,
 * and the JavaScript type names the option and path checks quote).
 */
export const KINDS: readonly Rule[] = [
  [/^a number$/, () => msg('a number')],
  [/^a string$/, () => msg('a string')],
  [/^a boolean$/, () => msg('a boolean')],
  [/^true or false$/, () => msg('true or false')],
  [/^an object$/, () => msg('an object')],
  [/^a list$/, () => msg('a list')],
  [/^a whole number$/, () => msg('a whole number')],
  [/^one of (.+)$/, (values) => msg(str`one of ${values}`)],
  [/^a list of (\d+) numbers$/, (count) => msg(str`a list of ${count} numbers`)],
  [/^a list of (\d+) whole numbers$/, (count) => msg(str`a list of ${count} whole numbers`)],
  [/^a list of (\d+) positive numbers$/, (count) => msg(str`a list of ${count} positive numbers`)],
  [/^a list of (\d+) numbers between 0 and 1$/, (count) => msg(str`a list of ${count} numbers between 0 and 1`)],
  // One allowed value (oneOf in scene-issues.ts): a quoted text or a JSON literal, the same in every language.
  [/^(".*"|-?\d[\d.e+-]*|true|false|null)$/, (literal) => literal],
];
