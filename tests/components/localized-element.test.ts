// Every element renders again by itself when the language changes (LocalizedElement,
// @lit/localize's updateWhenLocaleChanges), and a refusal's reason on screen is said again
// once its sayings have loaded after the first screen (src/i18n/locale.ts).
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { html } from 'lit';
import { issueText } from '../../src/i18n/issue-text.ts';
import { useLocale } from '../../src/i18n/locale.ts';
import { LocalizedElement } from '../../src/ui/controls/localized-element.ts';
import '../../src/ui/controls/rt-theme-toggle.ts';
import type { Issue } from '../../src/util/issue.ts';
import { mount, unmountAll } from './mount.ts';

const refusal: Issue = { path: 'camera.fov', reason: { code: 'outOfRange', lowest: 1, highest: 179, got: { kind: 'literal', text: '400' } } };

/** An element that shows one refused file's reason, as the file panel does. */
class TestRefusal extends LocalizedElement {
  override render() {
    return html`<p>${issueText(refusal)}</p>`;
  }
}
customElements.define('test-refusal', TestRefusal);

declare global {
  interface HTMLElementTagNameMap {
    'test-refusal': TestRefusal;
  }
}

const shown = (element: Element) => element.shadowRoot?.textContent?.replace(/\s+/g, ' ').trim();

afterEach(unmountAll);
afterAll(() => useLocale('en'));

describe('a language change', () => {
  it('renders a mounted element again in the new language, and back', async () => {
    const toggle = await mount('rt-theme-toggle');
    expect(shown(toggle)).toBe('Theme: system');
    await useLocale('nl');
    await toggle.updateComplete;
    expect(shown(toggle)).toBe('Thema: systeem');
    await useLocale('en');
    await toggle.updateComplete;
    expect(shown(toggle)).toBe('Theme: system');
  });

  it("says a reason on screen again in Dutch once the reasons' sayings arrive", async () => {
    const element = await mount('test-refusal');
    expect(shown(element)).toBe('camera.fov: must be between 1 and 179, got 400');
    await useLocale('nl');
    await expect.poll(async () => (await element.updateComplete, shown(element))).toBe('camera.fov: moet tussen 1 en 179 liggen, maar is 400');
  });
});
