import { LATER_TEXT_KEY } from '../quest/later-text-key.ts';
import type { Locale } from '../quest/localized-text.ts';
import { levelTextsLocale } from './level-catalog-browser.ts';

/**
 * The words of a level text that loads later ("Explain more", scripts/level-texts-plugin.ts):
 * fetched when a learner first opens one, in the language the levels were loaded in. Any
 * other text is its own words.
 */

let loaded: { locale: Locale | null; texts: Record<string, string> } | null = null;

/** The words now, when they need no loading (or are loaded already); else null. */
export function laterLevelTextNow(text: string): string | null {
  if (!text.startsWith(LATER_TEXT_KEY)) return text;
  if (loaded?.locale !== levelTextsLocale()) return null;
  return loaded.texts[text.slice(LATER_TEXT_KEY.length)] ?? '';
}

/** The words, loading the later texts first when needed. */
export async function laterLevelText(text: string): Promise<string> {
  const now = laterLevelTextNow(text);
  if (now !== null) return now;
  const locale = levelTextsLocale();
  const texts = locale === 'nl' ? (await import('virtual:level-more/nl')).default : (await import('virtual:level-more/en')).default;
  loaded = { locale, texts };
  return texts[text.slice(LATER_TEXT_KEY.length)] ?? '';
}
