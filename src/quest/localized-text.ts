import { z } from 'zod';
import { chosenBy } from './chosen-schema.ts';

/**
 * Level text is keyed by locale (DESIGN.md: English first, Dutch follows). A text in a level
 * file is either a plain string, which is English, or an object with one string per
 * language: `{ "en": "Select the ball.", "nl": "Selecteer de bal." }`. English is always
 * there, so a missing translation falls back to it instead of to nothing.
 */

export const LOCALES = ['en', 'nl'] as const;
export type Locale = (typeof LOCALES)[number];

export type LocalizedText = string | { en: string; nl?: string };

/** Four times the longest text of the game's levels (an "explain more" of 1,300 characters). */
export const TEXT_MAX = 5000;

const text = () => z.string().trim().min(1).max(TEXT_MAX);

// Built once: a zod schema costs far more to build than to run (a survey took 40 ms to read when they were built per text).
const plainText = text();
const perLocale = z.strictObject({ en: text(), nl: text().optional() });

export const localizedTextSchema: z.ZodType<LocalizedText> = chosenBy((input): z.ZodType<LocalizedText> =>
  typeof input === 'object' && input !== null && !Array.isArray(input) ? perLocale : plainText,
);

/** The text in the learner's language, or the English one when it has not been translated. */
export function localize(text: LocalizedText, locale: Locale): string {
  if (typeof text === 'string') return text;
  return text[locale] ?? text.en;
}
