import { html, type CSSResultGroup, type TemplateResult } from 'lit';
import { LocalizedElement } from './localized-element.ts';
import { controlStyles } from './controls.css.ts';

/** The detail of a control's `input` and `change` events. */
export type ValueDetail<T> = { value: T };

/**
 * What every panel control (rt-slider, rt-switch, rt-choice, rt-color-field,
 * rt-vector-field) has: a visible label, a tooltip that is also its accessible description,
 * a name for its owner, a disabled state, and the owner's reason for refusing its last
 * change (`error`), shown next to it until the owner clears it.
 */
export class ControlElement extends LocalizedElement {
  static override properties = {
    label: {},
    tooltip: {},
    name: { reflect: true },
    disabled: { type: Boolean, reflect: true },
    error: {},
  };

  static override styles: CSSResultGroup = controlStyles;

  /** Visible label. */
  declare label: string;
  /** Shown on hover and read as the control's description (aria-describedby="tip"). */
  declare tooltip: string;
  /** Identifies the control to its owner (and to tests); not shown. */
  declare name: string;
  declare disabled: boolean;
  /** The owner's reason for refusing the last change, shown until cleared. */
  declare error: string | undefined;

  constructor() {
    super();
    this.label = '';
    this.tooltip = '';
    this.name = '';
    this.disabled = false;
  }

  /** Fires `input` or `change` with `value` (bubbling and composed, so the owner gets it from the shadow root). */
  protected emit<T>(type: 'input' | 'change', value: T): void {
    this.dispatchEvent(new CustomEvent<ValueDetail<T>>(type, { detail: { value }, bubbles: true, composed: true }));
  }

  /** The tooltip as hidden text with id "tip", for aria-describedby (hover titles are not read everywhere). */
  protected tip(): TemplateResult {
    return html`<span id="tip" hidden>${this.tooltip}</span>`;
  }
}
