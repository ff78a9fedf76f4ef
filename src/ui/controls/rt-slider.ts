import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import { live } from 'lit/directives/live.js';
import { ControlElement } from './control-element.ts';
import { FrameThrottle } from './frame-throttle.ts';
import { FieldTyping } from './field-typing.ts';
import { formatNumber, readTypedNumber } from './number-input.ts';

/**
 * @summary A labelled slider with a number field: drag, use the keys (arrows, Page Up/Down,
 * Home, End) or type a value.
 *
 * Typed text may use a decimal comma ("0,5") and, with unit "%", percent. A typed value
 * outside [inputMin, inputMax] is clamped and a note says so ("Clamped to 1–170"); text
 * that is not a number keeps the old value and says what to type. The element is
 * controlled: it shows `value` and asks for changes by events, so a change the owner
 * refuses springs back.
 *
 * @fires input - CustomEvent<ValueDetail<number>> while dragging, at most once per frame.
 * @fires change - CustomEvent<ValueDetail<number>> when a value is committed (released,
 *   a key step, Enter or leaving the field).
 */
export class RtSlider extends ControlElement {
  static override properties = {
    ...ControlElement.properties,
    min: { type: Number },
    max: { type: Number },
    step: { type: Number },
    inputMin: { type: Number, attribute: 'input-min' },
    inputMax: { type: Number, attribute: 'input-max' },
    value: { type: Number },
    unit: {},
    whole: { type: Boolean },
  };

  static override styles = [
    ControlElement.styles,
    css`
      /* Its own stacking context, so that a drag repaints the slider alone: without it every
         step (its thumb, its number) painted the whole scrolling column of panels again, a few
         milliseconds of the page's main thread per step on this project's machine
         (docs/benchmark-log.md, issue 38). It clips nothing: focus rings still show whole. */
      :host {
        isolation: isolate;
      }
      /* The unit sits inside the field's box, so every field's right edge lines up; the box is
         a label, so a tap anywhere on it (its border, the unit) reaches the field. */
      .number {
        display: flex;
        align-items: center;
        box-sizing: border-box;
        height: var(--rt-target);
        border: 1px solid var(--rt-control-border);
        border-radius: 6px;
        background: var(--rt-bg);
      }
      .number:has(input:focus-visible) {
        outline: 3px solid var(--rt-accent);
        outline-offset: 2px;
      }
      .number:has(input:disabled) {
        opacity: 0.5;
      }
      .number input {
        width: 8ch;
        height: 30px;
        border: 0;
        background: transparent;
        text-align: right;
        outline: none;
      }
      .number input:disabled {
        opacity: 1;
      }
      .unit {
        padding-right: 8px;
      }
      input[type='range'] {
        display: block;
        width: 100%;
        height: var(--rt-target);
        margin: 0;
        accent-color: var(--rt-accent);
        cursor: pointer;
      }
      input[type='range']:disabled {
        cursor: not-allowed;
      }
      ::slotted(*) {
        margin: 0;
        color: var(--rt-muted);
        font-size: 0.8125rem;
      }
    `,
  ];

  /** Slider range (default 0–1) and step (default 0.01). */
  declare min: number;
  declare max: number;
  declare step: number;
  /** The range a typed value may have; defaults to the slider's (a schema may allow more). */
  declare inputMin: number | undefined;
  declare inputMax: number | undefined;
  declare value: number;
  /** Shown after the number ("°", "m"); "%" shows a fraction 0..1 as percent. */
  declare unit: string;
  /** Only whole numbers (typed fractions are rounded). */
  declare whole: boolean;

  private readonly typing = new FieldTyping<number>(this, {
    read: (text) =>
      readTypedNumber(text, { min: this.inputMin ?? this.min, max: this.inputMax ?? this.max, whole: this.whole, percent: this.unit === '%' }, this.unit),
    commit: (value) => this.commit(value),
  });
  private readonly inputs = new FrameThrottle<number>((value) => this.emit('input', value));
  /** The value under the thumb while dragging, until the owner's value catches up. */
  private dragged: number | undefined;

  constructor() {
    super();
    this.min = 0;
    this.max = 1;
    this.step = 0.01;
    this.value = 0;
    this.unit = '';
    this.whole = false;
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.inputs.cancel();
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    // A new value from the owner ends a drag's local value (it has caught up or moved on).
    if (changed.has('value') && this.dragged === this.value) this.dragged = undefined;
  }

  private onRangeInput(event: Event): void {
    // The native event is composed and would reach the owner as a second, detail-less `input`.
    event.stopPropagation();
    this.dragged = Number((event.target as HTMLInputElement).value);
    this.typing.reset();
    this.inputs.push(this.dragged);
    this.requestUpdate();
  }

  private onRangeChange(event: Event): void {
    const value = Number((event.target as HTMLInputElement).value);
    this.inputs.cancel();
    this.typing.message.show(undefined);
    this.commit(value);
  }

  /** Asks for `value`, then shows whatever the owner's value is (it may have refused). */
  private commit(value: number): void {
    this.dragged = undefined;
    this.emit('change', value);
    this.requestUpdate();
  }

  override render() {
    const shown = this.dragged ?? this.value;
    const text = formatNumber(shown, this.step, this.unit === '%');
    return html`
      <div class="row">
        <label class="label" for="number" title=${this.tooltip}>${this.label}</label>
        <label class="number">
          <input
            id="number"
            type="text"
            inputmode="decimal"
            autocomplete="off"
            spellcheck="false"
            aria-label=${msg(str`${this.label}, typed value`)}
            aria-describedby="tip message"
            title=${this.tooltip}
            .value=${live(this.typing.text(0, text))}
            ?disabled=${this.disabled}
            @input=${(event: Event) => this.typing.input(0, event)}
            @change=${() => this.typing.change(0)}
            @keydown=${(event: KeyboardEvent) => this.typing.keydown(0, event)}
          />
          ${this.unit ? html`<span class="unit" aria-hidden="true">${this.unit}</span>` : nothing}
        </label>
      </div>
      <input
        type="range"
        aria-label=${this.label}
        aria-describedby="tip message"
        aria-valuetext=${this.unit ? `${text} ${this.unit}` : text}
        title=${this.tooltip}
        min=${this.min}
        max=${this.max}
        step=${this.step}
        .value=${live(String(shown))}
        ?disabled=${this.disabled}
        @input=${this.onRangeInput}
        @change=${this.onRangeChange}
      />
      ${this.tip()}
      <slot></slot>
      ${this.typing.message.render(this.error)}
    `;
  }
}

customElements.define('rt-slider', RtSlider);

declare global {
  interface HTMLElementTagNameMap {
    'rt-slider': RtSlider;
  }
}
