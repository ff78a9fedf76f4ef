import { msg, str } from '@lit/localize';
import { css, html } from 'lit';
import { live } from 'lit/directives/live.js';
import type { Color } from '../../scene/scene.ts';
import { colorToHex, hexToColor } from './color-hex.ts';
import { ControlElement } from './control-element.ts';
import { FieldTyping } from './field-typing.ts';
import { FrameThrottle } from './frame-throttle.ts';

/**
 * @summary A labelled colour: the system colour picker, and a hex field ("#e6261a") to
 * type or paste a colour with the keyboard.
 *
 * `value` is the scene's linear [r, g, b] in 0..1, shown as round(c · 255) with no gamma
 * (see color-hex.ts: the tracer writes its image without one). Controlled: shows `value`,
 * asks by events.
 *
 * @fires input - CustomEvent<ValueDetail<Color>> while picking, at most once per frame.
 * @fires change - CustomEvent<ValueDetail<Color>> when a colour is committed (the picker
 *   closes, Enter, or leaving the hex field).
 */
export class RtColorField extends ControlElement {
  static override properties = {
    ...ControlElement.properties,
    value: { attribute: false },
  };

  static override styles = [
    ControlElement.styles,
    css`
      .pick {
        display: flex;
        align-items: center;
        gap: 8px;
      }
      input[type='color'] {
        box-sizing: border-box;
        width: max(40px, var(--rt-target));
        height: var(--rt-target);
        padding: 2px;
        border: 1px solid var(--rt-control-border);
        border-radius: 6px;
        background: var(--rt-surface);
        cursor: pointer;
      }
      input[type='text'] {
        width: 9ch;
        font-family: ui-monospace, monospace;
      }
    `,
  ];

  declare value: Color;

  private readonly typing = new FieldTyping<Color>(this, {
    read: (text) => {
      const value = hexToColor(text);
      return value ? { value } : { note: msg('Type a colour as #rrggbb, for example #ff8000') };
    },
    commit: (value) => this.commit(value),
  });
  private readonly inputs = new FrameThrottle<Color>((value) => this.emit('input', value));

  constructor() {
    super();
    this.value = [1, 1, 1];
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.inputs.cancel();
  }

  private onPickerInput(event: Event): void {
    // Native `input` is composed: stop it so the owner only sees ours, with a detail.
    event.stopPropagation();
    const color = hexToColor((event.target as HTMLInputElement).value);
    if (color) this.inputs.push(color);
  }

  private onPickerChange(event: Event): void {
    const color = hexToColor((event.target as HTMLInputElement).value);
    this.inputs.cancel();
    if (color) this.commit(color);
  }

  /** Asks for `color`, then shows the owner's value (the old one if it refused). */
  private commit(color: Color): void {
    this.emit('change', color);
    this.requestUpdate();
  }

  override render() {
    const hex = colorToHex(this.value);
    return html`
      <div class="row">
        <label class="label" for="picker" title=${this.tooltip}>${this.label}</label>
        <span class="pick">
          <input
            id="picker"
            type="color"
            title=${this.tooltip}
            aria-describedby="tip message"
            .value=${live(hex)}
            ?disabled=${this.disabled}
            @input=${this.onPickerInput}
            @change=${this.onPickerChange}
          />
          <input
            type="text"
            autocomplete="off"
            spellcheck="false"
            maxlength="7"
            aria-label=${msg(str`${this.label}, hex code`)}
            aria-describedby="tip message"
            title=${this.tooltip}
            .value=${live(this.typing.text(0, hex))}
            ?disabled=${this.disabled}
            @input=${(event: Event) => this.typing.input(0, event)}
            @change=${() => this.typing.change(0)}
            @keydown=${(event: KeyboardEvent) => this.typing.keydown(0, event)}
          />
        </span>
      </div>
      ${this.tip()}
      ${this.typing.message.render(this.error)}
    `;
  }
}

customElements.define('rt-color-field', RtColorField);

declare global {
  interface HTMLElementTagNameMap {
    'rt-color-field': RtColorField;
  }
}
