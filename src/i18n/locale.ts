import { configureLocalization } from '@lit/localize';
import { sourceLocale, targetLocales } from '../locales/locale-codes.ts';
import type { Locale } from '../quest/localized-text.ts';
import { ISSUE_TEXTS_LOADED, loadIssueTranslation } from './issue-text.ts';
import { pickLocale, readRememberedLocale, rememberLocale } from './locale-choice.ts';
import { LazyModule } from '../util/lazy-module.ts';

/**
 * The app's language at run time (@lit/localize in runtime mode): the Dutch messages are a
 * module of their own (src/locales/nl.ts, built from xliff/nl.xlf), loaded only when Dutch
 * is chosen. `<html lang>` follows, so screen readers, hyphenation and the browser's own
 * controls use the right language.
 */

/**
 * The Dutch messages: tried a few times, then failed for good (a tab of a build that a newer
 * one replaced, offline): the app goes on in English and says so
 * (src/ui/controls/locale-problem.ts).
 */
const dutchTexts = new LazyModule(() => import('../locales/nl.ts'));

const localization = configureLocalization({
  sourceLocale,
  targetLocales,
  loadLocale: () => dutchTexts.load(),
});

/** Why the Dutch texts could not be loaded (the browser's words), or null while they could be or were not asked for. */
export function dutchTextsProblem(): string | null {
  return dutchTexts.state === 'failed' ? dutchTexts.problem || 'unknown' : null;
}

const storage = () => localStorage;

/** The language the app speaks now. */
export function currentLocale(): Locale {
  return localization.getLocale() === 'nl' ? 'nl' : 'en';
}

/**
 * Switches to `locale`: the messages are loaded, then `<html lang>` follows, and every element
 * renders again by itself (src/ui/controls/localized-element.ts).
 * Resolves to the language in use afterwards: when the Dutch module cannot be loaded (the
 * network dropped), the app goes on in the language it had instead of not starting.
 */
export async function useLocale(locale: Locale): Promise<Locale> {
  try {
    await localization.setLocale(locale);
  } catch (error) {
    console.error(`The ${locale} texts could not be loaded`, error);
  }
  document.documentElement.lang = currentLocale();
  // The reasons a refused file is said for (issue-text.ts) are rare: their patterns load after
  // the first screen, and a reason on screen before they arrive is said again once they have
  // (each element renders again on this event, src/ui/controls/localized-element.ts).
  if (currentLocale() !== 'en') {
    // The page asked now is the one told later (a test's stand-in window may be gone by then).
    const page = window;
    loadIssueTranslation().then(
      () => page.dispatchEvent(new Event(ISSUE_TEXTS_LOADED)),
      (error: unknown) => console.warn('The translated reasons could not be loaded; they are shown in English', error),
    );
  }
  return currentLocale();
}

/** The learner's choice in the menu: used now and remembered for the next visit. */
export function chooseLocale(locale: Locale): Promise<Locale> {
  rememberLocale(storage, locale);
  return useLocale(locale);
}

/**
 * The language for the page being opened (see pickLocale): the assignment's when one is
 * played, else the address's `?lang=`, else the remembered choice, else the browser's
 * language, else English. Awaited
 * before the first render, so no English flashes up first.
 */
export function startLocale(assignment: Locale | null = null): Promise<Locale> {
  return useLocale(
    pickLocale({ assignment, search: location.search, remembered: readRememberedLocale(storage), browser: globalThis.navigator?.languages ?? [] }),
  );
}
