import { css, html } from 'lit';
import { live } from 'lit/directives/live.js';
import { ControlElement } from './control-element.ts';
import { messageLine } from './status-message.ts';

/** One choice of an rt-choice. */
export interface ChoiceOption {
  value: string;
  label: string;
  /** Shown on hover over this choice. */
  tooltip?: string;
}

/**
 * @summary A labelled choice of a few options as segmented buttons: real radio buttons in
 * a fieldset, so Tab enters the group and the arrow keys move the choice (the browser's
 * own radio behaviour). The chosen segment is filled and its text bold, not only coloured.
 * Controlled: shows `value`, asks by events.
 *
 * @fires change - CustomEvent<ValueDetail<string>> with the chosen option's value.
 */
export class RtChoice extends ControlElement {
  static override properties = {
    ...ControlElement.properties,
    options: { attribute: false },
    value: {},
  };

  static override styles = [
    ControlElement.styles,
    css`
      fieldset {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        justify-content: space-between;
        gap: 4px 8px;
        margin: 0;
        padding: 0;
        border: 0;
        min-width: 0;
      }
      legend {
        float: left;
        padding: 0;
        min-height: var(--rt-target);
        line-height: var(--rt-target);
      }
      .segments {
        display: flex;
        flex: 1 0 auto;
        border: 1px solid var(--rt-control-border);
        border-radius: 6px;
        overflow: hidden;
      }
      .segment {
        position: relative;
        display: flex;
        flex: 1 1 auto;
        align-items: center;
        justify-content: center;
        min-height: var(--rt-target);
        padding: 0 12px;
        cursor: pointer;
        background: var(--rt-surface);
      }
      .segment + .segment {
        border-left: 1px solid var(--rt-border);
      }
      .segment:has(input:checked) {
        background: var(--rt-accent);
        color: var(--rt-accent-text);
        font-weight: 600;
      }
      .segment:has(input:focus-visible) {
        outline: 3px solid var(--rt-accent);
        outline-offset: -3px;
        z-index: 1;
      }
      .segment:has(input:checked:focus-visible) {
        outline-color: var(--rt-text);
      }
      .segment:has(input:disabled) {
        opacity: 0.5;
        cursor: not-allowed;
      }
      /* The radio itself stays focusable and in the accessibility tree; the segment is its look. */
      input {
        position: absolute;
        inset: 0;
        margin: 0;
        opacity: 0;
        cursor: inherit;
      }
    `,
  ];

  declare options: ChoiceOption[];
  declare value: string;

  constructor() {
    super();
    this.options = [];
    this.value = '';
  }

  private onChange(event: Event): void {
    const value = (event.target as HTMLInputElement).value;
    this.emit('change', value);
    // Show the owner's choice: the old one when it refused.
    this.requestUpdate();
  }

  override render() {
    return html`
      <fieldset aria-describedby="tip message" title=${this.tooltip}>
        <legend>${this.label}</legend>
        <span class="segments">
          ${this.options.map(
            (option) => html`<label class="segment" title=${option.tooltip ?? this.tooltip}>
              <input
                type="radio"
                name="choice"
                .value=${option.value}
                .checked=${live(option.value === this.value)}
                ?disabled=${this.disabled}
                @input=${(event: Event) => event.stopPropagation()}
                @change=${this.onChange}
              />
              <span>${option.label}</span>
            </label>`,
          )}
        </span>
      </fieldset>
      ${this.tip()}
      ${messageLine(this.error, true, 'message')}
    `;
  }
}

customElements.define('rt-choice', RtChoice);

declare global {
  interface HTMLElementTagNameMap {
    'rt-choice': RtChoice;
  }
}
