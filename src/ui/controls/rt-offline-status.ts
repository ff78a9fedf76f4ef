import { css, html } from 'lit';
import { LocalizedElement } from './localized-element.ts';
import { offlineCopy, type OfflineCopyState } from '../../app/offline-copy.ts';
import { offlineCopyText } from './offline-copy-text.ts';

/**
 * @summary One line in the Menu: whether this browser keeps the app for use without a
 * network (src/app/offline-copy.ts), kept current while the service worker stores it.
 * A warning sign as well as the words when it does not.
 */
export class RtOfflineStatus extends LocalizedElement {
  static override properties = { state: { state: true } };

  static override styles = css`
    :host {
      display: block;
      padding-top: 8px;
      border-top: 1px solid var(--rt-border);
    }
    p {
      margin: 0;
      font-size: 0.8125rem;
      color: var(--rt-muted);
    }
    .not-stored {
      color: var(--rt-text);
    }
    .not-stored::before {
      content: '⚠ ';
      color: var(--rt-danger);
    }
  `;

  declare state: OfflineCopyState;
  private unsubscribe: (() => void) | null = null;

  constructor() {
    super();
    this.state = offlineCopy.state;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.state = offlineCopy.state;
    this.unsubscribe = offlineCopy.subscribe((state) => (this.state = state));
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.unsubscribe?.();
    this.unsubscribe = null;
  }

  override render() {
    return html`<p class=${this.state.kind} data-testid="offline-status">${offlineCopyText(this.state)}</p>`;
  }
}

customElements.define('rt-offline-status', RtOfflineStatus);

declare global {
  interface HTMLElementTagNameMap {
    'rt-offline-status': RtOfflineStatus;
  }
}
