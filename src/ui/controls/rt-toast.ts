import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { LocalizedElement } from './localized-element.ts';

interface Toast {
  id: number;
  text: string;
  tone: 'info' | 'error';
}

/** How long a message stays at least: long enough to read two lines at school-reading speed. */
const SHOW_MS = 6000;
/** …and longer for a longer one: about 1,000 characters a minute, a slow reader's pace. */
const MS_PER_CHARACTER = 60;

/**
 * @summary Short messages in the page's bottom right corner: a refused change
 * ("settings.supersampling: must be between 1 and 8, got 40"), a broken file, a hint that
 * something happened.
 * Announced to screen readers: two live regions that are always there (role=status for
 * news, role=alert for problems), so that a message added to them is read out.
 *
 * Above everything: the element is a manual popover, in the browser's top layer, where it
 * is put again on top each time a message comes, above the level map, the Menu and a dialog
 * opened before it.
 */
export class RtToast extends LocalizedElement {
  static override properties = { toasts: { state: true } };

  static override styles = css`
    /* In the bottom right corner, over the lab's task column (at most 280 px wide, as
       lab-layout.css.ts makes it): there it covers neither the 3D view, with the rays and
       pads a task names or rings, nor the panels a hint rings. On a small screen that is
       the column beside (or below) the view too. The lab moves it to the column's top, or
       over the panels, so that it covers neither the level's intro nor the current task
       (toast-place.ts). */
    :host {
      position: fixed;
      inset: auto var(--rt-space) calc(var(--rt-space) * 2) auto;
      margin: 0;
      padding: 0;
      border: 0;
      background: transparent;
      overflow: visible;
      pointer-events: none;
      width: max-content;
      max-width: min(264px, calc(100vw - var(--rt-space) * 2));
    }
    /* Where the task column narrows to 240–260 px (lab-layout.css.ts), so does the message. */
    @media (max-width: 1180px) {
      :host {
        max-width: min(244px, calc(100vw - var(--rt-space) * 2));
      }
    }
    /* The UA hides a closed popover with display: none; only an open one is laid out. */
    :host(:popover-open),
    .region {
      display: flex;
      flex-direction: column;
      gap: var(--rt-space);
    }
    .region:empty {
      display: none;
    }
    .toast {
      pointer-events: auto;
      display: flex;
      gap: var(--rt-space);
      align-items: start;
      padding: 10px 12px;
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
      color: var(--rt-text);
      box-shadow: var(--rt-shadow);
      border-left: 4px solid var(--rt-accent);
      white-space: pre-line;
    }
    .error {
      border-left-color: var(--rt-danger);
    }
    button {
      font: inherit;
      border: 0;
      background: none;
      color: var(--rt-muted);
      cursor: pointer;
      min-width: 28px;
      min-height: 28px;
    }
  `;

  declare toasts: Toast[];
  private lastId = 0;

  constructor() {
    super();
    this.toasts = [];
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.popover = 'manual';
    this.raise();
  }

  /** Shows a message for a few seconds (longer for a long one), above everything on the page. */
  show(text: string, tone: Toast['tone'] = 'info'): void {
    const toast = { id: ++this.lastId, text, tone };
    this.raise();
    this.toasts = [...this.toasts.slice(-2), toast];
    setTimeout(() => this.dismiss(toast.id), Math.max(SHOW_MS, text.length * MS_PER_CHARACTER));
  }

  /**
   * On top of the top layer: elements there stack in the order they were shown, so the
   * popover is hidden and shown again (in one task: the live regions stay, nothing flickers).
   */
  private raise(): void {
    if (!this.isConnected || typeof this.showPopover !== 'function') return;
    if (this.matches(':popover-open')) this.hidePopover();
    this.showPopover();
  }

  private dismiss(id: number): void {
    this.toasts = this.toasts.filter((t) => t.id !== id);
  }

  override render() {
    const region = (tone: Toast['tone']) =>
      this.toasts
        .filter((t) => t.tone === tone)
        .map(
          (t) => html`<div class="toast ${t.tone}">
            <span>${t.text}</span>
            <button @click=${() => this.dismiss(t.id)} aria-label=${msg('Dismiss message')} title=${msg('Dismiss message')}>✕</button>
          </div>`,
        );
    return html`<div class="region" role="status" aria-live="polite">${region('info')}</div>
      <div class="region" role="alert" aria-live="assertive">${region('error')}</div>`;
  }
}

customElements.define('rt-toast', RtToast);

declare global {
  interface HTMLElementTagNameMap {
    'rt-toast': RtToast;
  }
}
