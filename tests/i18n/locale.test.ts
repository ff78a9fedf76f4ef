// The run-time wiring of the language, on a stand-in page (the unit tests run without a browser):
// the real generated Dutch module is loaded, msg() answers in Dutch, <html lang> follows, and
// an element that asked to (LocalizedElement, via updateWhenLocaleChanges) renders again.
import { msg, str, updateWhenLocaleChanges } from '@lit/localize';
import type { ReactiveController } from 'lit';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { LOCALE_KEY } from '../../src/i18n/locale-choice.ts';
import { progressProblemText } from '../../src/i18n/progress-problem-text.ts';
import { MemoryStorage, type ProgressProblem } from '../../src/quest/progress-store.ts';

/** A stand-in element on the page: counts its re-renders, as a Lit element connects its controllers. */
class FakeElement {
  updates = 0;
  readonly controllers: ReactiveController[] = [];
  addController(controller: ReactiveController): void {
    this.controllers.push(controller);
  }
  connect(): void {
    for (const controller of this.controllers) controller.hostConnected?.();
  }
  requestUpdate(): void {
    this.updates++;
  }
}

describe('the app language at run time', () => {
  const storage = new MemoryStorage();
  const lit = new FakeElement();
  const page = { documentElement: { lang: 'en' } };
  let locale: typeof import('../../src/i18n/locale.ts');
  let numbers: typeof import('../../src/i18n/number-format.ts');

  beforeAll(async () => {
    vi.stubGlobal('window', new EventTarget());
    vi.stubGlobal('document', page);
    vi.stubGlobal('localStorage', storage);
    vi.stubGlobal('location', { search: '?lang=nl' });
    locale = await import('../../src/i18n/locale.ts');
    // What LocalizedElement's constructor does (src/ui/controls/localized-element.ts).
    updateWhenLocaleChanges(lit as unknown as Parameters<typeof updateWhenLocaleChanges>[0]);
    lit.connect();
    numbers = await import('../../src/i18n/number-format.ts');
  });

  afterAll(() => {
    vi.unstubAllGlobals();
  });

  it('starts in the language of the address, in Dutch from the generated catalogue', async () => {
    expect(await locale.startLocale()).toBe('nl');
    expect(locale.currentLocale()).toBe('nl');
    expect(page.documentElement.lang).toBe('nl');
    expect(msg('Cancel')).toBe('Annuleren');
    const points = 7;
    expect(msg(str`${points} points`)).toBe('7 punten');
    expect(lit.updates).toBe(1);
    // The address is no choice of the learner's: nothing is remembered.
    expect(storage.getItem(LOCALE_KEY)).toBeNull();
  });

  it("puts an assignment's language before the address's", async () => {
    expect(await locale.startLocale('en')).toBe('en');
    expect(msg('Cancel')).toBe('Cancel');
    expect(page.documentElement.lang).toBe('en');
  });

  it("remembers the learner's choice in the menu, and starts from it next time", async () => {
    expect(await locale.chooseLocale('nl')).toBe('nl');
    expect(storage.getItem(LOCALE_KEY)).toBe('nl');
    vi.stubGlobal('location', { search: '' });
    await locale.chooseLocale('en');
    storage.setItem(LOCALE_KEY, 'nl');
    expect(await locale.startLocale()).toBe('nl');
    expect(msg('Menu')).toBe('Menu');
    expect(msg('Your progress')).toBe('Jouw voortgang');
  });

  it('writes numbers the way the current language does, with one formatter kept across a change', async () => {
    const count = numbers.localNumbers();
    const share = numbers.localNumbers({ minimumFractionDigits: 1, maximumFractionDigits: 1 });
    await locale.useLocale('nl');
    expect([count.format(8624), share.format(99.46)]).toEqual(['8.624', '99,5']);
    await locale.useLocale('en');
    expect([count.format(8624), share.format(99.46)]).toEqual(['8,624', '99.5']);
  });

  it("words the progress store's problems in the learner's language", async () => {
    const problem: ProgressProblem = { kind: 'damaged', reasons: [], backupKey: 'rtq.progress.backup.1', raw: '{' };
    const repaired: ProgressProblem = { kind: 'repaired', reasons: ['settings.locale: must be one of en, nl, got "fr" (default)'], backupKey: null, raw: '{}' };
    await locale.useLocale('nl');
    expect(progressProblemText(problem, 0)).toBe(
      'Je opgeslagen voortgang is beschadigd en kon niet worden gelezen. Je begint weer vanaf het begin. De opgeslagen gegevens zijn bewaard zoals ze waren: download of herstel ze via het Menu (Beschadigde gegevens).',
    );
    expect(progressProblemText(repaired, 40)).toMatch(
      /^Een deel van je opgeslagen voortgang was beschadigd; wat beschadigd was, is weggelaten \(1: settings\.locale\); de rest is bewaard: 40 punten\. Er is geen ruimte om een kopie te bewaren/,
    );
    await locale.useLocale('en');
    expect(progressProblemText(problem, 0)).toMatch(/^Your saved progress is damaged/);
    expect(progressProblemText(repaired, 40)).toMatch(
      /^Part of your saved progress was damaged, and what was damaged is left out \(1: settings\.locale\); the rest is kept: 40 points\. There is no room/,
    );
  });
});
