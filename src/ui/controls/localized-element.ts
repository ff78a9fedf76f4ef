import { updateWhenLocaleChanges } from '@lit/localize';
import { LitElement } from 'lit';
import { LATER_TEXTS_ARRIVED } from '../../i18n/later-texts.ts';

/**
 * The base of every element of the app: it renders again when the language changes, so each
 * msg() in its render is asked anew (@lit/localize's updateWhenLocaleChanges, what its
 * @localized() decorator does), and when texts arrive after the first screen
 * (src/i18n/later-texts.ts). tests/i18n/localized-elements.test.ts checks
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
    window.addEventListener(LATER_TEXTS_ARRIVED, this.renderAgain);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    window.removeEventListener(LATER_TEXTS_ARRIVED, this.renderAgain);
  }
}
