/**
 * A text in the app's languages (DESIGN.md: English first, Dutch follows): either a plain
 * string, which is English, or an object with one string per language,
 * `{ "en": "Select the ball.", "nl": "Selecteer de bal." }`. English is always there, so a
 * missing translation falls back to it instead of to nothing. Level texts (src/quest) and
 * the names in a scene (src/scene) are written this way.
 */

export const LOCALES = ['en', 'nl'] as const;
export type Locale = (typeof LOCALES)[number];

export type LocalizedText = string | { en: string; nl?: string };

/** The text in the learner's language, or the English one when it has not been translated. */
export function localize(text: LocalizedText, locale: Locale): string {
  if (typeof text === 'string') return text;
  return text[locale] ?? text.en;
}
