import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from './localized-element.ts';
import { controlStyles } from './controls.css.ts';

/**
 * @summary In the place of a part of the app whose code could not be loaded (a teacher
 * page, an on-demand panel, the 3D view), after its bounded tries (LazyModule): what failed,
 * the two ways it happens, the browser's reason, and a Reload button, the one thing that
 * helps. It stays: nothing on the page tries again by itself.
 *
 * `text`: what could not be loaded ("This page could not be loaded."); `reason`: the
 * browser's words, shown small for whoever helps; `closable`: a Close button too, for a
 * message over a page that goes on without what failed (the Dutch texts).
 */
export class RtLoadProblem extends LocalizedElement {
  static override properties = { text: {}, reason: {}, closable: { type: Boolean } };

  static override styles = [
    controlStyles,
    css`
      div {
        display: grid;
        gap: 8px;
        justify-items: start;
        max-width: 60ch;
        padding: 12px;
        border: 1px solid var(--rt-border);
        border-left: 5px solid var(--rt-danger);
        border-radius: var(--rt-radius);
        background: var(--rt-surface);
      }
      p {
        margin: 0;
      }
      .text {
        font-weight: 600;
      }
      .reason {
        color: var(--rt-muted);
        font-size: 0.8125rem;
        overflow-wrap: anywhere;
      }
      .buttons {
        display: flex;
        gap: 8px;
      }
      button.close {
        background: none;
        color: inherit;
        border-color: var(--rt-border);
      }
      button {
        min-height: var(--rt-target);
        padding: 0 12px;
        border: 1px solid var(--rt-accent);
        border-radius: 6px;
        background: var(--rt-accent);
        color: var(--rt-accent-text);
        font: inherit;
        font-weight: 600;
        cursor: pointer;
      }
    `,
  ];

  declare text: string;
  declare reason: string;
  declare closable: boolean;

  constructor() {
    super();
    this.text = '';
    this.reason = '';
    this.closable = false;
  }

  override render() {
    return html`<div role="alert">
      <p class="text">${this.text}</p>
      <p>${msg('Either a newer version of the app has replaced the one in this tab, or there is no connection. Reload the page (once you are online) to load it again.')}</p>
      ${this.reason ? html`<p class="reason">${this.reason}</p>` : ''}
      <p class="buttons">
        <button type="button" @click=${() => location.reload()}>${msg('Reload')}</button>
        ${this.closable ? html`<button type="button" class="close" @click=${() => this.remove()}>${msg('Close')}</button>` : ''}
      </p>
    </div>`;
  }
}

customElements.define('rt-load-problem', RtLoadProblem);

declare global {
  interface HTMLElementTagNameMap {
    'rt-load-problem': RtLoadProblem;
  }
}
