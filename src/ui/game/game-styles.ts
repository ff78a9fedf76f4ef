import { css } from 'lit';
import { controlStyles } from '../controls/controls.css.ts';
import { visuallyHiddenStyles } from '../controls/visually-hidden.css.ts';

/**
 * What the game's elements (task panel, level map, dialogs) share on top of the panel
 * controls' styles: the accent button for the one next step, cards, and status tags that
 * say their state in words and a symbol as well as colour.
 */
export const gameStyles = [
  controlStyles,
  visuallyHiddenStyles,
  css`
    button.primary {
      border-color: var(--rt-accent);
      background: var(--rt-accent);
      color: var(--rt-accent-text);
      font-weight: 600;
    }
    button.link {
      min-height: var(--rt-target);
      padding: 0 4px;
      border: 0;
      background: none;
      color: var(--rt-accent);
      text-decoration: underline;
    }
    .card {
      padding: 12px;
      border: 1px solid var(--rt-border);
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
    }
    .tag {
      display: inline-block;
      padding: 0 6px;
      border-radius: 999px;
      border: 1px solid currentColor;
      font-size: 0.75rem;
      line-height: 1.5;
      white-space: nowrap;
    }
    .muted {
      color: var(--rt-muted);
    }
    p {
      margin: 0 0 8px;
    }
    .hint {
      padding: 6px 8px;
      border-radius: 6px;
      background: var(--rt-accent-soft);
    }
    details.more summary {
      cursor: pointer;
      color: var(--rt-accent);
      min-height: 28px;
      display: flex;
      align-items: center;
    }
    details.more p {
      padding: 6px 8px;
      background: var(--rt-surface-2);
      border-radius: 6px;
    }
    /* The header's popovers (badges, menu) open under the header, at the right. */
    [popover] {
      position: fixed;
      inset: auto;
      margin: 0;
      top: 52px;
      right: 16px;
      padding: 12px;
      border: 1px solid var(--rt-border);
      border-radius: var(--rt-radius);
      background: var(--rt-surface);
      color: var(--rt-text);
      box-shadow: var(--rt-shadow);
    }
    h2,
    h3 {
      margin: 0 0 8px;
      line-height: 1.25;
    }
  `,
];

/**
 * A panel inside a task card (a challenge, a code lab): a block set off a little from the task's
 * text, its heading the size of the text around it.
 */
export const taskPanelStyles = css`
  :host {
    display: block;
    margin: 8px 0;
  }
  h3 {
    margin: 0 0 6px;
    font-size: 1rem;
  }
`;

/** Sends a bubbling, composed event, so it reaches the lab through shadow roots. */
export function fire<T>(from: HTMLElement, type: string, detail: T): void {
  from.dispatchEvent(new CustomEvent<T>(type, { detail, bubbles: true, composed: true }));
}
