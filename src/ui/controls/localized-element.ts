import { updateWhenLocaleChanges } from '@lit/localize';
import { LitElement } from 'lit';
import { ISSUE_TEXTS_LOADED } from '../../i18n/issue-text.ts';

/**
 * The base of every element of the app: it renders again when the language changes, so each
 * msg() in its render is asked anew (@lit/localize's updateWhenLocaleChanges, what its
 * @localized() decorator does), and when the translated reasons of a refused file arrive
 * after the first screen (src/i18n/locale.ts). tests/i18n/localized-elements.test.ts checks
 * that no element extends LitElement past it.
 */
export class LocalizedElement extends LitElement {
  private readonly renderAgain = () => this.requestUpdate();

  constructor() {
    super();
    updateWhenLocaleChanges(this);
  }

  override connectedCallback(): void {
    super.connectedCallback();
    window.addEventListener(ISSUE_TEXTS_LOADED, this.renderAgain);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    window.removeEventListener(ISSUE_TEXTS_LOADED, this.renderAgain);
  }
}
