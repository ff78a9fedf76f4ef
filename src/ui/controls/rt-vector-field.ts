import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { live } from 'lit/directives/live.js';
import { ControlElement } from './control-element.ts';
import { FieldTyping } from './field-typing.ts';
import { formatNumber, readTypedNumber } from './number-input.ts';

/**
 * @summary A labelled row of number fields for a position, rotation, scale or size
 * (x, y, z or width, height): the keyboard way to place things the gizmo drags.
 *
 * Each field takes typed numbers as rt-slider's does (decimal comma, clamping with a note,
 * unreadable text keeps the old value). Controlled: shows `value`, asks by events.
 *
 * @fires change - CustomEvent<ValueDetail<number[]>>: the whole vector with one component
 *   changed, when a field is committed (Enter or leaving it).
 */
export class RtVectorField extends ControlElement {
  static override properties = {
    ...ControlElement.properties,
    axes: { attribute: false },
    value: { attribute: false },
    min: { type: Number },
    max: { type: Number },
    step: { type: Number },
    unit: {},
    whole: { type: Boolean },
    limitReason: { attribute: false },
  };

  static override styles = [
    ControlElement.styles,
    css`
      .caption {
        margin-bottom: 4px;
      }
      .fields {
        display: flex;
        gap: 8px;
      }
      .field {
        flex: 1 1 0;
        display: flex;
        align-items: center;
        gap: 4px;
        min-width: 0;
      }
      .axis {
        color: var(--rt-muted);
      }
      .field input {
        flex: 1 1 auto;
        width: 100%;
        text-align: right;
      }
    `,
  ];

  /** Short visible names of the components, one field each (default x, y, z). */
  declare axes: string[];
  declare value: number[];
  /** Typed range of every component (default −10000..10000, the scene's coordinates). */
  declare min: number;
  declare max: number;
  /** Decimals shown follow the step (default 0.01). */
  declare step: number;
  /** After the label ("m", "°"). */
  declare unit: string;
  declare whole: boolean;
  /** Why the range ends where it does, added to the note when typed text is clamped ('' for none). */
  declare limitReason: string;

  private readonly typing = new FieldTyping<number>(this, {
    read: (text) => readTypedNumber(text, { min: this.min, max: this.max, whole: this.whole, why: this.limitReason || undefined }, this.unit),
    commit: (component, index) => {
      const value = this.value.map((v, i) => (i === index ? component : v));
      this.emit('change', value);
    },
  });

  constructor() {
    super();
    this.axes = ['x', 'y', 'z'];
    this.value = [0, 0, 0];
    this.min = -10_000;
    this.max = 10_000;
    this.step = 0.01;
    this.unit = '';
    this.whole = false;
    this.limitReason = '';
  }

  override render() {
    const unit = this.unit ? ` (${this.unit})` : '';
    return html`
      <div class="caption" id="label" title=${this.tooltip}>${this.label}${unit}</div>
      <div class="fields" role="group" aria-labelledby="label" aria-describedby="tip message">
        ${this.axes.map(
          (axis, index) => html`<label class="field" title=${this.tooltip}>
            <span class="axis" aria-hidden="true">${axis}</span>
            <input
              type="text"
              inputmode="decimal"
              autocomplete="off"
              spellcheck="false"
              aria-label=${msg(str`${this.label} ${axis}`)}
              .value=${live(this.typing.text(index, formatNumber(this.value[index] ?? 0, this.step)))}
              ?disabled=${this.disabled}
              @input=${(event: Event) => this.typing.input(index, event)}
              @change=${() => this.typing.change(index)}
              @keydown=${(event: KeyboardEvent) => this.typing.keydown(index, event)}
            />
          </label>`,
        )}
      </div>
      ${this.tip()}
      ${this.typing.message.render(this.error)}
    `;
  }
}

customElements.define('rt-vector-field', RtVectorField);

declare global {
  interface HTMLElementTagNameMap {
    'rt-vector-field': RtVectorField;
  }
}
