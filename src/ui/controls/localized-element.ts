import { updateWhenLocaleChanges } from '@lit/localize';
import { LitElement } from 'lit';

/**
 * The base of every element of the app: it renders again when the language changes, so each
 * msg() in its render is asked anew (@lit/localize's updateWhenLocaleChanges, what its
 * @localized() decorator does). tests/i18n/localized-elements.test.ts checks that no element
 * extends LitElement past it.
 */
export class LocalizedElement extends LitElement {
  constructor() {
    super();
    updateWhenLocaleChanges(this);
  }
}
