import { z } from 'zod';
import { chosenBy } from './chosen-schema.ts';
import type { LocalizedText } from '../util/localized-text.ts';

/**
 * Level texts are localized texts (src/util/localized-text.ts): a plain English string or
 * `{ "en": …, "nl": … }`. This is their schema, with the length a level text may have.
 */

export { LOCALES, localize, type Locale, type LocalizedText } from '../util/localized-text.ts';

/** Four times the longest text of the game's levels (an "explain more" of 1,300 characters). */
export const TEXT_MAX = 5000;

const text = () => z.string().trim().min(1).max(TEXT_MAX);

// Built once: a zod schema costs far more to build than to run (a survey took 40 ms to read when they were built per text).
const plainText = text();
const perLocale = z.strictObject({ en: text(), nl: text().optional() });

export const localizedTextSchema: z.ZodType<LocalizedText> = chosenBy((input): z.ZodType<LocalizedText> =>
  typeof input === 'object' && input !== null && !Array.isArray(input) ? perLocale : plainText,
);
