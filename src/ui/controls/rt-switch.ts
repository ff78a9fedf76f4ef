import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { live } from 'lit/directives/live.js';
import { ControlElement } from './control-element.ts';
import { messageLine } from './status-message.ts';

/** The detail of rt-switch's `change` event. */
export type CheckedDetail = { checked: boolean };

/**
 * @summary A labelled on/off switch: a real checkbox with role="switch", so Space toggles
 * it and screen readers say "on"/"off". The knob's side and the "On"/"Off" text show the
 * state, not the colour alone. Controlled: shows `checked`, asks by events.
 *
 * @fires change - CustomEvent<CheckedDetail> when toggled.
 */
export class RtSwitch extends ControlElement {
  static override properties = {
    ...ControlElement.properties,
    checked: { type: Boolean, reflect: true },
  };

  static override styles = [
    ControlElement.styles,
    css`
      label.row {
        cursor: pointer;
      }
      .state {
        display: flex;
        align-items: center;
        gap: 8px;
        color: var(--rt-muted);
      }
      input {
        appearance: none;
        position: relative;
        flex: none;
        box-sizing: border-box;
        width: 44px;
        height: 24px;
        margin: 4px 0;
        border: 1px solid var(--rt-control-border);
        border-radius: 12px;
        background: var(--rt-bg);
        cursor: pointer;
        transition: background-color 0.15s;
      }
      input::before {
        content: '';
        position: absolute;
        top: 3px;
        left: 3px;
        width: 16px;
        height: 16px;
        border-radius: 50%;
        background: var(--rt-muted);
        transition: transform 0.15s;
      }
      input:checked {
        border-color: var(--rt-accent);
        background: var(--rt-accent);
      }
      input:checked::before {
        background: var(--rt-accent-text);
        transform: translateX(20px);
      }
      @media (prefers-reduced-motion: reduce) {
        input,
        input::before {
          transition: none;
        }
      }
    `,
  ];

  declare checked: boolean;

  constructor() {
    super();
    this.checked = false;
  }

  private onChange(event: Event): void {
    const checked = (event.target as HTMLInputElement).checked;
    this.dispatchEvent(new CustomEvent<CheckedDetail>('change', { detail: { checked }, bubbles: true, composed: true }));
    // Show the owner's state: unchanged when it refused.
    this.requestUpdate();
  }

  override render() {
    return html`
      <label class="row" title=${this.tooltip}>
        <span class="label">${this.label}</span>
        <span class="state">
          <span aria-hidden="true">${this.checked ? msg('On') : msg('Off')}</span>
          <input
            type="checkbox"
            role="switch"
            aria-describedby="tip message"
            .checked=${live(this.checked)}
            ?disabled=${this.disabled}
            @input=${(event: Event) => event.stopPropagation()}
            @change=${this.onChange}
          />
        </span>
      </label>
      ${this.tip()}
      ${messageLine(this.error, true, 'message')}
    `;
  }
}

customElements.define('rt-switch', RtSwitch);

declare global {
  interface HTMLElementTagNameMap {
    'rt-switch': RtSwitch;
  }
}
