import { msg } from '@lit/localize';
import { css, html, type PropertyValues } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import { controlStyles } from '../controls/controls.css.ts';
import { gestureHelp, type KeyHelp, keyHelp } from '../../view/view-commands.ts';

/**
 * @summary A dialog listing every key and every mouse and touch gesture of the 3D view, from
 * the same table the view reads its keys from (so the list cannot fall behind). Opened by
 * the view's Help button or "?"; closed by Escape, its Close button or a click outside it.
 *
 * @fires help-closed - Event: the dialog closed (the owner sets `open` back to false).
 */
export class RtHelpPanel extends LocalizedElement {
  static override properties = { open: { type: Boolean, reflect: true } };

  static override styles = [
    controlStyles,
    css`
      dialog {
        box-sizing: border-box;
        width: min(40rem, calc(100vw - 32px));
        max-height: calc(100vh - 32px);
        padding: 0;
        border: 1px solid var(--rt-border);
        border-radius: var(--rt-radius, 10px);
        background: var(--rt-surface);
        color: var(--rt-text);
        font-family: var(--rt-font);
        font-size: 0.875rem;
        box-shadow: 0 12px 40px rgb(0 0 0 / 0.3);
      }
      dialog::backdrop {
        background: rgb(10 14 20 / 0.45);
      }
      header {
        position: sticky;
        top: 0;
        display: flex;
        align-items: center;
        justify-content: space-between;
        padding: 12px 16px;
        border-bottom: 1px solid var(--rt-border);
        background: var(--rt-surface);
      }
      h2 {
        margin: 0;
        font-size: 1.05rem;
      }
      h3 {
        margin: 16px 16px 4px;
        font-size: 0.9rem;
        color: var(--rt-muted);
      }
      table {
        width: calc(100% - 32px);
        margin: 0 16px 8px;
        border-collapse: collapse;
      }
      th,
      td {
        padding: 6px 0;
        border-bottom: 1px solid var(--rt-border);
        text-align: left;
        vertical-align: top;
        font-weight: normal;
      }
      th {
        width: 40%;
        padding-right: 12px;
      }
      kbd {
        display: inline-block;
        min-width: 1.4em;
        margin: 1px 2px 1px 0;
        padding: 1px 6px;
        border: 1px solid var(--rt-border);
        border-bottom-width: 2px;
        border-radius: 5px;
        background: var(--rt-bg);
        font: inherit;
        font-size: 0.8125rem;
        text-align: center;
      }
    `,
  ];

  /** Whether the dialog is shown (modal). */
  declare open: boolean;

  constructor() {
    super();
    this.open = false;
  }

  override render() {
    return html`<dialog aria-labelledby="title" @close=${this.closed} @click=${this.clickedBackdrop}>
      <header>
        <h2 id="title">${msg('Keys and gestures of the 3D view')}</h2>
        <button title=${msg('Close this help (Esc)')} @click=${() => this.dialog?.close()} autofocus>${msg('Close')}</button>
      </header>
      <h3>${msg('Keys (click the 3D view first)')}</h3>
      ${this.table(keyHelp(), true)}
      <h3>${msg('Mouse and touch')}</h3>
      ${this.table(gestureHelp(), false)}
    </dialog>`;
  }

  protected override updated(changed: PropertyValues<this>): void {
    if (!changed.has('open')) return;
    const dialog = this.dialog;
    if (!dialog) return;
    if (this.open && !dialog.open) dialog.showModal();
    if (!this.open && dialog.open) dialog.close();
  }

  private get dialog(): HTMLDialogElement | null {
    return this.renderRoot.querySelector('dialog');
  }

  private table(rows: KeyHelp[], keys: boolean) {
    return html`<table>
      <tbody>
        ${rows.map(
          (row) => html`<tr>
            <th scope="row">${keys ? row.keys.map((key) => html`<kbd>${key}</kbd>`) : row.keys.join(' / ')}</th>
            <td>${row.description}</td>
          </tr>`,
        )}
      </tbody>
    </table>`;
  }

  private readonly closed = () => {
    this.open = false;
    this.dispatchEvent(new Event('help-closed', { bubbles: true, composed: true }));
  };

  /** A click on the backdrop (the dialog element itself, outside its content) closes it. */
  private readonly clickedBackdrop = (event: MouseEvent) => {
    const dialog = this.dialog;
    if (!dialog || event.target !== dialog) return;
    const box = dialog.getBoundingClientRect();
    const inside = event.clientX >= box.left && event.clientX <= box.right && event.clientY >= box.top && event.clientY <= box.bottom;
    if (!inside) dialog.close();
  };
}

customElements.define('rt-help-panel', RtHelpPanel);

declare global {
  interface HTMLElementTagNameMap {
    'rt-help-panel': RtHelpPanel;
  }
}
