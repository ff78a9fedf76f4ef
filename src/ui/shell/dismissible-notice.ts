import { msg } from '@lit/localize';
import { css, html, nothing, type CSSResultGroup, type PropertyDeclarations, type TemplateResult } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';

/**
 * A note over the page that stays until the user puts it away with its ✕ (the link's error,
 * the preview's "nothing is saved"): a card with a coloured left edge (`--notice-edge`) and
 * the close button. A subclass places the host and says what the card holds.
 */
export abstract class DismissibleNotice extends LocalizedElement {
  static override properties: PropertyDeclarations = { dismissed: { state: true } };

  static override styles: CSSResultGroup = css`
    div {
      display: flex;
      gap: 8px;
      background: var(--rt-surface);
      color: var(--rt-text);
      border: 1px solid var(--rt-border);
      border-left: 5px solid var(--notice-edge, var(--rt-accent));
      border-radius: var(--rt-radius);
      box-shadow: var(--rt-shadow);
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

  /** The card with `content` and the ✕; `role` is `alert` for a problem, `status` for information. */
  protected notice(role: 'alert' | 'status', content: TemplateResult): TemplateResult | typeof nothing {
    if (this.dismissed) return nothing;
    return html`<div role=${role}>
      ${content}
      <button type="button" aria-label=${msg('Dismiss message')} title=${msg('Dismiss message')} @click=${() => (this.dismissed = true)}>✕</button>
    </div>`;
  }
}
