import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { DismissibleNotice } from './dismissible-notice.ts';

/**
 * @summary The note over a teacher's level preview: that nothing of it is kept, so a teacher
 * does not mistake it for a pupil's session. It can be put away; it comes back on reload.
 */
export class RtPreviewNotice extends DismissibleNotice {
  static override styles = [
    DismissibleNotice.styles,
    css`
      :host {
        position: fixed;
        bottom: 8px;
        left: 8px;
        z-index: 50;
        max-width: min(460px, 90vw);
      }
      div {
        align-items: center;
        padding: 6px 8px 6px 12px;
        font-size: 0.9rem;
      }
    `,
  ];

  override render() {
    return this.notice(
      'status',
      html`<span><strong>${msg('Preview of one level')}</strong> · ${msg('Nothing is saved: the progress and times of this preview are forgotten when the tab closes.')}</span>`,
    );
  }
}

customElements.define('rt-preview-notice', RtPreviewNotice);

declare global {
  interface HTMLElementTagNameMap {
    'rt-preview-notice': RtPreviewNotice;
  }
}
