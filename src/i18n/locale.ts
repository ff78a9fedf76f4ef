import { configureLocalization } from '@lit/localize';
import { sourceLocale, targetLocales } from '../locales/locale-codes.ts';
import type { Locale } from '../quest/localized-text.ts';
import { loadIssueTranslation } from './issue-text.ts';
import { LATER_TEXTS_ARRIVED } from './later-texts.ts';
import { pickLocale, readRememberedLocale, rememberLocale } from './locale-choice.ts';
import { LazyModule } from '../util/lazy-module.ts';

/**
 * The app's language at run time (@lit/localize in runtime mode): the Dutch messages are
 * modules of their own (built from xliff/nl.xlf), loaded only when Dutch is chosen: those of
 * the first screen (src/locales/nl.ts) before it, those of the parts that load later
 * (nl-later.ts) while it is up, added to the first ones (scripts/split-dutch-catalogue.ts). `<html lang>` follows, so screen readers, hyphenation and the browser's own
 * controls use the right language.
 */

/**
 * The Dutch messages: tried a few times, then failed for good (a tab of a build that a newer
 * one replaced, offline): the app goes on in English and says so
 * (src/ui/controls/locale-problem.ts).
 */
const dutchTexts = new LazyModule(() => import('../locales/nl.ts'));
const laterDutchTexts = new LazyModule(() => import('../locales/nl-later.ts'));

/** The later Dutch messages, added to the first screen's (lit-localize reads them from that object). */
async function addLaterDutchTexts(): Promise<void> {
  const [first, later] = await Promise.all([dutchTexts.load(), laterDutchTexts.load()]);
  Object.assign(first.templates, later.templates);
}

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

/** Settles once the texts of the later parts are in (or could not be loaded): tests await it. */
let laterTexts: Promise<void> = Promise.resolve();
export function laterTextsSettled(): Promise<void> {
  return laterTexts;
}

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
  // The later parts' messages and the reasons a refused file is said for (issue-text.ts) load
  // after the first screen; a text on screen before they arrive is said again once they have
  // (src/i18n/later-texts.ts). The page asked now is the one told later (a test's stand-in
  // window may be gone by then).
  if (currentLocale() !== 'en') {
    const page = window;
    const arrived = (): void => void page.dispatchEvent(new Event(LATER_TEXTS_ARRIVED));
    laterTexts = addLaterDutchTexts().then(arrived, (error: unknown) =>
      console.warn('The Dutch texts of later pages could not be loaded; they are shown in English', error),
    );
    loadIssueTranslation().then(arrived, (error: unknown) => console.warn('The translated reasons could not be loaded; they are shown in English', error));
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
