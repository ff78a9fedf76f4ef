import { LOCALES, type Locale } from '../quest/localized-text.ts';

/**
 * Which language the app speaks, decided without touching the page (so it can be tested):
 * a teacher's assignment sets it for the class; otherwise `?lang=nl` in the address (a link
 * a teacher hands out, or a bookmark); otherwise what the learner last picked in the menu;
 * otherwise the first of the browser's languages the app speaks (a Dutch browser opens in
 * Dutch on the first visit); otherwise English, the language the app is written in.
 */

/** The localStorage key of the learner's own choice in the menu. */
export const LOCALE_KEY = 'rt-locale';

/** What is known when the app starts; each may be missing. */
export interface LocaleSources {
  /** The language of the teacher's assignment being played, if one is. */
  assignment?: Locale | null;
  /** `location.search`, e.g. `?lang=nl`. */
  search?: string;
  /** The learner's remembered choice, as read from storage. */
  remembered?: string | null;
  /** The browser's languages in its order of preference (`navigator.languages`, e.g. `['nl-NL', 'en']`). */
  browser?: readonly string[];
}

/** `value` when it names a language of the app ('nl', 'NL', ' en '), else null. */
export function parseLocale(value: string | null | undefined): Locale | null {
  const code = value?.trim().toLowerCase();
  return LOCALES.find((locale) => locale === code) ?? null;
}

/** The language to use: assignment > `?lang=` > remembered choice > the browser's languages > English. */
export function pickLocale(sources: LocaleSources): Locale {
  const fromAddress = parseLocale(new URLSearchParams(sources.search ?? '').get('lang'));
  return sources.assignment ?? fromAddress ?? parseLocale(sources.remembered) ?? browserLocale(sources.browser ?? []) ?? 'en';
}

/** The first of the browser's languages the app speaks, by its primary subtag ('nl-BE' is Dutch), or null. */
export function browserLocale(languages: readonly string[]): Locale | null {
  for (const language of languages) {
    const locale = parseLocale(language.split('-')[0]);
    if (locale) return locale;
  }
  return null;
}

/** The remembered choice, or null; a browser that blocks storage (it throws) counts as none. */
export function readRememberedLocale(storage: () => Pick<Storage, 'getItem'>): string | null {
  try {
    return storage().getItem(LOCALE_KEY);
  } catch {
    return null;
  }
}

/** Remembers the learner's choice; where storage is blocked or full it lasts for this visit only. */
export function rememberLocale(storage: () => Pick<Storage, 'setItem'>, locale: Locale): void {
  try {
    storage().setItem(LOCALE_KEY, locale);
  } catch {
    // The choice still applies now; the next visit starts from the address or English.
  }
}
