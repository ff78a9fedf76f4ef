import { msg } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * @summary The note over a teacher's level preview: that nothing of it is kept, so a teacher
 * does not mistake it for a pupil's session. It can be put away; it comes back on reload.
 */
export class RtPreviewNotice extends LocalizedElement {
  static override properties = { dismissed: { state: true } };

  static override styles = css`
    :host {
      position: fixed;
      bottom: 8px;
      left: 8px;
      z-index: 50;
      max-width: min(460px, 90vw);
    }
    div {
      display: flex;
      gap: 8px;
      align-items: center;
      padding: 6px 8px 6px 12px;
      background: var(--rt-surface);
      color: var(--rt-text);
      border: 1px solid var(--rt-border);
      border-left: 5px solid var(--rt-accent);
      border-radius: var(--rt-radius);
      box-shadow: var(--rt-shadow);
      font-size: 0.9rem;
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

  declare dismissed: boolean;

  constructor() {
    super();
    this.dismissed = false;
  }

  override render() {
    if (this.dismissed) return nothing;
    return html`<div role="status">
      <span><strong>${msg('Preview of one level')}</strong> · ${msg('Nothing is saved: the progress and times of this preview are forgotten when the tab closes.')}</span>
      <button type="button" aria-label=${msg('Dismiss message')} title=${msg('Dismiss message')} @click=${() => (this.dismissed = true)}>✕</button>
    </div>`;
  }
}

customElements.define('rt-preview-notice', RtPreviewNotice);

declare global {
  interface HTMLElementTagNameMap {
    'rt-preview-notice': RtPreviewNotice;
  }
}
