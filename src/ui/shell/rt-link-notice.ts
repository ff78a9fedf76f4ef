import { css, html, nothing } from 'lit';
import { DismissibleNotice } from './dismissible-notice.ts';

/**
 * @summary A message across the top of the page that stays until it is dismissed: why an
 * assignment link did not open (a toast would vanish before a student could show it to the
 * teacher). A new `text` shows again after a dismissal.
 */
export class RtLinkNotice extends DismissibleNotice {
  static override properties = { text: {} };

  static override styles = [
    DismissibleNotice.styles,
    css`
      :host {
        position: fixed;
        top: 8px;
        left: 50%;
        transform: translateX(-50%);
        z-index: 50;
        max-width: min(720px, 94vw);
        --notice-edge: var(--rt-danger);
      }
      div {
        align-items: start;
        padding: 10px 12px;
      }
      span::before {
        content: '⚠ ';
        color: var(--rt-danger);
      }
    `,
  ];

  declare text: string;

  constructor() {
    super();
    this.text = '';
  }

  override willUpdate(changed: Map<string, unknown>): void {
    if (changed.has('text')) this.dismissed = false;
  }

  override render() {
    return this.text === '' ? nothing : this.notice('alert', html`<span>${this.text}</span>`);
  }
}

customElements.define('rt-link-notice', RtLinkNotice);

declare global {
  interface HTMLElementTagNameMap {
    'rt-link-notice': RtLinkNotice;
  }
}
