import { msg } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * @summary A message across the top of the page that stays until it is dismissed: why an
 * assignment link did not open (a toast would vanish before a student could show it to the
 * teacher).
 */
export class RtLinkNotice extends LocalizedElement {
  static override properties = { text: {}, dismissed: { state: true } };

  static override styles = css`
    :host {
      position: fixed;
      top: 8px;
      left: 50%;
      transform: translateX(-50%);
      z-index: 50;
      max-width: min(720px, 94vw);
    }
    div {
      display: flex;
      gap: 8px;
      align-items: start;
      padding: 10px 12px;
      background: var(--rt-surface);
      color: var(--rt-text);
      border: 1px solid var(--rt-border);
      border-left: 5px solid var(--rt-danger);
      border-radius: var(--rt-radius);
      box-shadow: var(--rt-shadow);
    }
    span::before {
      content: '⚠ ';
      color: var(--rt-danger);
    }
    button {
      font: inherit;
      border: 0;
      background: none;
      color: var(--rt-muted);
      cursor: pointer;
      min-width: var(--rt-target);
      min-height: var(--rt-target);
    }
    button:focus-visible {
      outline: 3px solid var(--rt-focus);
    }
  `;

  declare text: string;
  declare dismissed: boolean;

  constructor() {
    super();
    this.text = '';
    this.dismissed = false;
  }

  override willUpdate(changed: Map<string, unknown>): void {
    if (changed.has('text')) this.dismissed = false;
  }

  override render() {
    if (this.dismissed || this.text === '') return nothing;
    return html`<div role="alert">
      <span>${this.text}</span>
      <button type="button" aria-label=${msg('Dismiss message')} title=${msg('Dismiss message')} @click=${() => (this.dismissed = true)}>✕</button>
    </div>`;
  }
}

customElements.define('rt-link-notice', RtLinkNotice);

declare global {
  interface HTMLElementTagNameMap {
    'rt-link-notice': RtLinkNotice;
  }
}
