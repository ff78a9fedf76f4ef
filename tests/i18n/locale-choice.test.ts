import { describe, expect, it } from 'vitest';
import { browserLocale, LOCALE_KEY, parseLocale, pickLocale, readRememberedLocale, rememberLocale } from '../../src/i18n/locale-choice.ts';
import { MemoryStorage } from '../../src/quest/progress-store.ts';

const blocked = (): Storage => {
  throw new DOMException('The operation is insecure.', 'SecurityError');
};

describe('choosing the language', () => {
  it('reads a language code loosely, and nothing else', () => {
    expect(parseLocale('nl')).toBe('nl');
    expect(parseLocale(' NL ')).toBe('nl');
    expect(parseLocale('en')).toBe('en');
    expect(parseLocale('de')).toBeNull();
    expect(parseLocale('nl-BE')).toBeNull();
    expect(parseLocale('')).toBeNull();
    expect(parseLocale(null)).toBeNull();
  });

  it('puts the assignment first, then the address, then the remembered choice, then English', () => {
    expect(pickLocale({ assignment: 'en', search: '?lang=nl', remembered: 'nl' })).toBe('en');
    expect(pickLocale({ assignment: 'nl', search: '?lang=en', remembered: 'en' })).toBe('nl');
    expect(pickLocale({ assignment: null, search: '?lang=nl', remembered: 'en' })).toBe('nl');
    expect(pickLocale({ search: '?x=1&lang=en', remembered: 'nl' })).toBe('en');
    expect(pickLocale({ search: '', remembered: 'nl' })).toBe('nl');
    expect(pickLocale({ search: '', remembered: null })).toBe('en');
    expect(pickLocale({})).toBe('en');
  });

  it("opens in the browser's language when nothing else chose one", () => {
    expect(pickLocale({ search: '', remembered: null, browser: ['nl-NL', 'en-US'] })).toBe('nl');
    expect(pickLocale({ search: '', remembered: null, browser: ['de-DE', 'nl-BE', 'en'] })).toBe('nl');
    expect(pickLocale({ search: '', remembered: null, browser: ['fr-FR', 'de'] })).toBe('en');
    // A choice made in the menu, the address or an assignment wins over the browser.
    expect(pickLocale({ search: '', remembered: 'en', browser: ['nl-NL'] })).toBe('en');
    expect(pickLocale({ search: '?lang=en', browser: ['nl-NL'] })).toBe('en');
    expect(pickLocale({ assignment: 'en', browser: ['nl'] })).toBe('en');
    expect(browserLocale([])).toBeNull();
    expect(browserLocale(['EN-gb'])).toBe('en');
  });

  it('passes over an address or a remembered value that names no language of the app', () => {
    expect(pickLocale({ search: '?lang=fr', remembered: 'nl' })).toBe('nl');
    expect(pickLocale({ search: '?lang=', remembered: 'klingon' })).toBe('en');
  });

  it('remembers the choice in storage, and treats blocked storage as no choice', () => {
    const storage = new MemoryStorage();
    expect(readRememberedLocale(() => storage as unknown as Storage)).toBeNull();
    rememberLocale(() => storage as unknown as Storage, 'nl');
    expect(storage.getItem(LOCALE_KEY)).toBe('nl');
    expect(readRememberedLocale(() => storage as unknown as Storage)).toBe('nl');
    expect(readRememberedLocale(blocked)).toBeNull();
    expect(() => rememberLocale(blocked, 'nl')).not.toThrow();
    const full = {
      setItem: () => {
        throw new DOMException('full', 'QuotaExceededError');
      },
    };
    expect(() => rememberLocale(() => full, 'en')).not.toThrow();
  });
});
