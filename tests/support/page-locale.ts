import { afterAll, beforeAll, vi } from 'vitest';
import { MemoryStorage } from '../../src/quest/progress-store.ts';

/**
 * Switches the app's language for real in a unit test (no browser): @lit/localize tells
 * `window` about the change and the app sets `<html lang>` and re-renders the page's
 * elements, so those get stand-ins first. The real generated Dutch module is loaded.
 * Returns the function that switches: `await speak('nl')`; call `vi.unstubAllGlobals()` after.
 */
export async function standInPage(): Promise<(locale: 'en' | 'nl') => Promise<void>> {
  vi.stubGlobal('window', new EventTarget());
  vi.stubGlobal('document', { documentElement: { lang: 'en' }, querySelectorAll: () => [] });
  vi.stubGlobal('localStorage', new MemoryStorage());
  vi.stubGlobal('location', { search: '' });
  const { laterTextsSettled, useLocale } = await import('../../src/i18n/locale.ts');
  const { loadIssueTranslation } = await import('../../src/i18n/issue-text.ts');
  return async (locale) => {
    await useLocale(locale);
    // The page loads the later parts' texts and the reasons' patterns after its first screen,
    // without waiting; a test waits.
    if (locale !== 'en') await Promise.all([laterTextsSettled(), loadIssueTranslation()]);
  };
}

/** Runs the tests of the enclosing `describe` in Dutch, and switches back to English after them. */
export function inDutch(): void {
  let speak: (locale: 'en' | 'nl') => Promise<void> = async () => {};
  beforeAll(async () => {
    speak = await standInPage();
    await speak('nl');
  });
  afterAll(async () => {
    await speak('en');
    vi.unstubAllGlobals();
  });
}
