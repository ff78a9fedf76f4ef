import { msg } from '@lit/localize';
import { css, html, LitElement } from 'lit';

interface Toast {
  id: number;
  text: string;
  tone: 'info' | 'error';
}

/** How long a message stays: long enough to read two lines at school-reading speed. */
const SHOW_MS = 6000;

/**
 * @summary Short messages at the bottom of the view: a refused change ("settings.supersampling:
 * must be between 1 and 8, got 40"), a broken file, a hint that something happened.
 * Announced to screen readers (role=status / alert).
 */
export class RtToast extends LitElement {
  static override properties = { toasts: { state: true } };

  static override styles = css`
    :host {
      position: absolute;
      left: 50%;
      bottom: calc(var(--rt-space) * 2);
      transform: translateX(-50%);
      display: flex;
      flex-direction: column;
      gap: var(--rt-space);
      z-index: 20;
      pointer-events: none;
      max-width: min(560px, 90%);
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

  /** Shows a message for a few seconds. */
  show(text: string, tone: Toast['tone'] = 'info'): void {
    const toast = { id: ++this.lastId, text, tone };
    this.toasts = [...this.toasts.slice(-2), toast];
    setTimeout(() => this.dismiss(toast.id), SHOW_MS);
  }

  private dismiss(id: number): void {
    this.toasts = this.toasts.filter((t) => t.id !== id);
  }

  override render() {
    return this.toasts.map(
      (t) => html`<div class="toast ${t.tone}" role=${t.tone === 'error' ? 'alert' : 'status'}>
        <span>${t.text}</span>
        <button @click=${() => this.dismiss(t.id)} aria-label=${msg('Dismiss message')} title=${msg('Dismiss message')}>✕</button>
      </div>`,
    );
  }
}

customElements.define('rt-toast', RtToast);

declare global {
  interface HTMLElementTagNameMap {
    'rt-toast': RtToast;
  }
}
