import { css, html } from 'lit';
import { LocalizedElement } from './localized-element.ts';
import { controlStyles } from './controls.css.ts';

/** The detail of rt-panel-section's `section-toggle` event. */
export type SectionToggleDetail = { name: string; open: boolean };

const STORAGE_PREFIX = 'rt-section:';

/**
 * @summary A collapsible part of a panel: a <details> whose <summary> holds the heading,
 * so it opens by click, touch, Enter or Space and says "expanded"/"collapsed" by itself.
 * Whether it is open is remembered per section in localStorage across visits.
 *
 * @slot - The section's controls.
 * @fires section-toggle - CustomEvent<SectionToggleDetail> (bubbles, composed) when the
 *   user opens or closes it (for the app's `panel.opened` action).
 */
export class RtPanelSection extends LocalizedElement {
  static override properties = {
    heading: {},
    name: { reflect: true },
    open: { type: Boolean, reflect: true },
  };

  static override styles = [
    controlStyles,
    css`
      details {
        border-bottom: 1px solid var(--rt-border);
      }
      summary {
        display: flex;
        align-items: center;
        gap: 8px;
        min-height: 40px;
        padding: 0 16px;
        cursor: pointer;
        list-style: none;
        user-select: none;
      }
      summary::-webkit-details-marker {
        display: none;
      }
      summary:focus-visible {
        outline-offset: -3px;
      }
      summary::before {
        content: '';
        flex: none;
        width: 6px;
        height: 6px;
        margin: 0 4px 0 2px;
        border-right: 2px solid var(--rt-muted);
        border-bottom: 2px solid var(--rt-muted);
        transform: rotate(-45deg);
        transition: transform 0.15s;
      }
      details[open] > summary::before {
        transform: translateY(-2px) rotate(45deg);
      }
      @media (prefers-reduced-motion: reduce) {
        summary::before {
          transition: none;
        }
      }
      h2 {
        margin: 0;
        font-size: 0.8125rem;
        font-weight: 700;
        letter-spacing: 0.04em;
        text-transform: uppercase;
        color: var(--rt-muted);
      }
      .content {
        display: grid;
        gap: 8px;
        padding: 0 16px 16px;
      }
    `,
  ];

  /** The visible heading (an h2 inside the summary). */
  declare heading: string;
  /** Key under which the open state is remembered; not translated, unlike the heading. */
  declare name: string;
  /** Open unless the user closed this section before (then the remembered state wins). */
  declare open: boolean;

  constructor() {
    super();
    this.heading = '';
    this.name = '';
    this.open = true;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    const remembered = readStorage(STORAGE_PREFIX + this.key);
    if (remembered !== null) this.open = remembered === 'open';
  }

  private get key(): string {
    return this.name || this.heading;
  }

  /**
   * A click on the heading (or Enter/Space on it) toggles at once: the <details> element's own
   * `toggle` event comes later, asynchronously, and a reload in between would forget the choice.
   */
  private onSummaryClick(event: Event): void {
    event.preventDefault();
    this.setOpen(!this.open);
  }

  /** Other ways a <details> opens (the browser's find-in-page reveals hidden text). */
  private onToggle(event: Event): void {
    this.setOpen((event.target as HTMLDetailsElement).open);
  }

  private setOpen(open: boolean): void {
    if (open === this.open) return;
    this.open = open;
    writeStorage(STORAGE_PREFIX + this.key, open ? 'open' : 'closed');
    this.dispatchEvent(new CustomEvent<SectionToggleDetail>('section-toggle', { detail: { name: this.key, open }, bubbles: true, composed: true }));
  }

  override render() {
    return html`
      <details ?open=${this.open} @toggle=${this.onToggle}>
        <summary @click=${this.onSummaryClick}><h2>${this.heading}</h2></summary>
        <div class="content"><slot></slot></div>
      </details>
    `;
  }
}

/** localStorage may be missing or refuse (private windows, storage turned off): then nothing is remembered. */
function readStorage(key: string): string | null {
  try {
    return localStorage.getItem(key);
  } catch {
    return null;
  }
}

function writeStorage(key: string, value: string): void {
  try {
    localStorage.setItem(key, value);
  } catch {
    // Not remembered; the section still works.
  }
}

customElements.define('rt-panel-section', RtPanelSection);

declare global {
  interface HTMLElementTagNameMap {
    'rt-panel-section': RtPanelSection;
  }
}
