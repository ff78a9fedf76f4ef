import { localize, type Locale, type LocalizedText } from './localized-text.ts';

/**
 * The one markup level texts have: an on-screen name (a panel, a section heading, a button,
 * a switch, a slider) is written between double asterisks, `Set **Time samples (k)** under
 * **Lens and shutter** to 4.`, so the task card can show it in bold (the learner sees which
 * words to look for on screen) and a test can check that each one is a label the screen
 * really shows (docs/levels.md, "Names on screen").
 *
 * A name is the text between a `**` and the next `**` on the same line, with no `*` in it;
 * a `**` without its partner is left as it is, so a slip shows up on screen as written
 * instead of turning the rest of the text bold.
 */

/** One piece of a text: words as written, or an on-screen name (`marked`). */
export interface TextPart {
  text: string;
  marked: boolean;
}

const NAME = /\*\*([^*\n]+)\*\*/g;

/** The text cut into its plain and marked pieces, in order; empty pieces are left out. */
export function markupParts(text: string): TextPart[] {
  const parts: TextPart[] = [];
  let from = 0;
  for (const match of text.matchAll(NAME)) {
    if (match.index > from) parts.push({ text: text.slice(from, match.index), marked: false });
    parts.push({ text: match[1], marked: true });
    from = match.index + match[0].length;
  }
  if (from < text.length) parts.push({ text: text.slice(from), marked: false });
  return parts;
}

/** The text without its marks, for places that show plain text (titles, tooltips, labels for screen readers). */
export function plainText(text: string): string {
  return text.replace(NAME, '$1');
}

/** A level's text in the learner's language, without its marks: a title, an alt text, the answer inside one of the app's sentences. */
export function plainLevelText(text: LocalizedText, locale: Locale): string {
  return plainText(localize(text, locale));
}

/** The on-screen names a text marks, in order. */
export function markedNames(text: string): string[] {
  return [...text.matchAll(NAME)].map((match) => match[1]);
}

/** Whether a `**` is left over once every name is taken out: a mark without its partner. */
export function hasStrayMark(text: string): boolean {
  return text.replace(NAME, '').includes('**');
}
