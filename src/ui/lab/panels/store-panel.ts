import { css, html, nothing, type CSSResultGroup, type PropertyValues, type TemplateResult } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { ifDefined } from 'lit/directives/if-defined.js';
import { issueText } from '../../../i18n/issue-text.ts';
import type { LabAction } from '../../../lab-state/lab-action.ts';
import type { LabState } from '../../../lab-state/lab-state.ts';
import type { Store } from '../../../lab-state/store.ts';
import type { Color } from '../../../scene/scene.ts';
import { LIMITS } from '../../../scene/scene-limits.ts';
import { LAB_CONTROLS, type LabPanel } from '../../../quest/lab-controls.ts';
import { controlIdOf, type ControlName } from './control-ids.ts';
import { GuideHostController } from '../guide-host.ts';
import { consumeStore } from '../store-context.ts';
import type { ValueDetail } from '../../controls/control-element.ts';
import { controlStyles } from '../../controls/controls.css.ts';
import { messageLine } from '../../controls/status-message.ts';
import '../../controls/rt-choice.ts';
import type { ChoiceOption } from '../../controls/rt-choice.ts';
import '../../controls/rt-color-field.ts';
import '../../controls/rt-panel-section.ts';
import '../../controls/rt-slider.ts';
import '../../controls/rt-switch.ts';
import type { CheckedDetail } from '../../controls/rt-switch.ts';
import '../../controls/rt-vector-field.ts';

/** The Phong terms that objects and lights both weigh. */
export type PhongTerm = 'ambient' | 'diffuse' | 'specular';
const PHONG_TERMS: PhongTerm[] = ['ambient', 'diffuse', 'specular'];

/** A control, or nothing when the level leaves it out. */
export type ControlPart = TemplateResult | typeof nothing;

/** What every control of a panel has: its name (control-ids.ts: its hint ring's id), label and tooltip. */
export interface ControlText<Name extends string = string> {
  name: Name;
  label: string;
  tooltip: string;
}

/** An rt-slider's setup; the typed range defaults to the slider's. */
export interface SliderSpec<Name extends string = string> extends ControlText<Name> {
  min: number;
  max: number;
  step: number;
  inputMin?: number;
  inputMax?: number;
  unit?: string;
  whole?: boolean;
  disabled?: boolean;
}

/** An rt-vector-field's setup. */
export interface VectorSpec<Name extends string = string> extends ControlText<Name> {
  axes?: string[];
  min: number;
  max: number;
  step: number;
  unit?: string;
  whole?: boolean;
  /** Why the range ends where it does, said when typed text is clamped. */
  limitReason?: string;
}

/**
 * What the lab's panels share: the store comes from the lab (context) or as a property, the
 * panel subscribes while it is on the page and shows the store's state (so a change from the
 * gizmo or a level shows at once), and every change goes up as a named action. A refused
 * action's reason is kept under the name of the control that asked, to be shown next to it.
 *
 * Each panel draws the controls of one panel of the levels' vocabulary (`controlPanel`, see
 * quest/lab-controls.ts): a control takes only a name that panel declares (control-ids.ts),
 * carries `data-guide="panel.control"` for it (the guide ring finds it through the panel's
 * GuideHostController), and `shownControls` narrows the panel to the level's choice; a
 * section left with no control is left out.
 */
export abstract class StorePanel<Panel extends LabPanel = LabPanel> extends LocalizedElement {
  static override properties = {
    store: { attribute: false },
    shownControls: { attribute: false },
    state: { state: true },
    errors: { state: true },
  };

  static override styles: CSSResultGroup = [
    controlStyles,
    css`
      .identity {
        display: flex;
        align-items: baseline;
        justify-content: space-between;
        gap: 8px;
        margin: 0;
      }
      .identity strong {
        font-size: 1rem;
        overflow-wrap: anywhere;
      }
      .muted {
        color: var(--rt-muted);
      }
      .empty p {
        margin: 0 0 8px;
      }
    `,
  ];

  /** The app's one store. */
  declare store: Store | undefined;
  /** The level's choice of this panel's controls (ids of lab-controls.ts), or undefined for all of them. */
  declare shownControls: readonly string[] | undefined;
  /** The panel of lab-controls.ts whose controls this element draws. */
  protected abstract readonly controlPanel: Panel;
  /** The store's state as last seen. */
  declare protected state: LabState | undefined;
  /** The store's reasons for refusing, by control name. */
  declare protected errors: Readonly<Record<string, string | undefined>>;
  private unsubscribe: (() => void) | undefined;
  /** The store `unsubscribe` belongs to. */
  private subscribed: Store | undefined;

  constructor() {
    super();
    this.errors = {};
    consumeStore(this, (store) => (this.store = store));
    new GuideHostController(this);
  }

  /** The level id of the control `name` ("pixels.columns" → "pixels"), unless levels cannot name it. */
  protected controlId(name: ControlName<Panel>): string | undefined {
    return controlIdOf(this.controlPanel, name);
  }

  /** Whether the level shows the control `name` (a narrowed panel hides controls levels cannot name). */
  protected shows(name: ControlName<Panel>): boolean {
    if (!this.shownControls) return true;
    const id = this.controlId(name);
    return id !== undefined && this.shownControls.includes(id);
  }

  /** The `data-guide` id of the control `name` ("tracer.supersampling"), if levels can name it. */
  protected guideOf(name: ControlName<Panel>): string | undefined {
    const id = this.controlId(name);
    return id === undefined ? undefined : `${this.controlPanel}.${id}`;
  }

  /** A section of `parts` under `lead` (the item's name); left out when the level hides all its controls. */
  protected section(heading: string, name: string, parts: ControlPart[], lead: ControlPart = nothing): ControlPart {
    if (this.shownControls && parts.every((part) => part === nothing)) return nothing;
    return html`<rt-panel-section heading=${heading} name=${name}>${lead}${parts}</rt-panel-section>`;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.listen();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.unsubscribe?.();
    this.unsubscribe = undefined;
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    if (changed.has('store')) this.listen();
  }

  /** Subscribes to `store` unless already subscribed to it (connecting and a first update both ask). */
  private listen(): void {
    if (this.unsubscribe && this.subscribed === this.store) return;
    this.unsubscribe?.();
    this.subscribed = this.store;
    this.unsubscribe = this.store?.subscribe((state) => this.show(state));
    this.show(this.store?.state);
  }

  private show(state: LabState | undefined): void {
    // Reasons belong to the item they were about: another selection starts clean.
    if (state?.selection !== this.state?.selection) this.errors = {};
    this.state = state;
  }

  /** Dispatches `action` for the control `name`; keeps (or clears) the reason it was refused. */
  /** Dispatches a control's change; `live` while the learner is still dragging it. */
  protected send(name: string, action: LabAction, live = false): void {
    const refused = this.store?.dispatch(action, { live });
    const error = refused?.map(issueText).join('\n');
    if (error !== this.errors[name]) this.errors = { ...this.errors, [name]: error };
  }

  /** The line for a refusal of a change asked by something other than a control (a button). */
  protected errorLine(name: string): TemplateResult {
    return messageLine(this.errors[name], true);
  }

  /** A section that says what to select, for when the panel's kind of item is not selected. */
  protected emptyState(heading: string, name: string, text: string, hint: string): TemplateResult {
    // The ring for any of the panel's controls goes here while they wait for a selection.
    const guides = LAB_CONTROLS[this.controlPanel]
      .filter((id) => !this.shownControls || this.shownControls.includes(id))
      .map((id) => `${this.controlPanel}.${id}`);
    return html`<rt-panel-section heading=${heading} name=${name}>
      <div class="empty" data-guide=${guides.join(' ')}>
        <p>${text}</p>
        <p class="muted">${hint}</p>
      </div>
    </rt-panel-section>`;
  }

  /** The selected item's name, and what kind of item it is. */
  protected identity(name: string, kind: string): TemplateResult {
    return html`<p class="identity"><strong>${name}</strong><span class="muted">${kind}</span></p>`;
  }

  /** A slider that dispatches `action(value)` while dragging and on commit; `hint` goes under it. */
  protected slider(spec: SliderSpec<ControlName<Panel>>, value: number, action: (value: number) => LabAction, hint?: TemplateResult | string): ControlPart {
    if (!this.shows(spec.name)) return nothing;
    const send = (event: CustomEvent<ValueDetail<number>>) => this.send(spec.name, action(event.detail.value), event.type === 'input');
    return html`<rt-slider
      name=${spec.name}
      data-guide=${ifDefined(this.guideOf(spec.name))}
      label=${spec.label}
      tooltip=${spec.tooltip}
      .min=${spec.min}
      .max=${spec.max}
      .step=${spec.step}
      .inputMin=${spec.inputMin}
      .inputMax=${spec.inputMax}
      unit=${spec.unit ?? ''}
      ?whole=${spec.whole ?? false}
      ?disabled=${spec.disabled ?? false}
      .value=${value}
      .error=${this.errors[spec.name]}
      @input=${send}
      @change=${send}
      >${hint === undefined ? nothing : html`<p>${hint}</p>`}</rt-slider
    >`;
  }

  /**
   * The three Phong shares, ambient, diffuse and specular, as sliders over 0..1 (an object's
   * ka, kd, ks and a light's shares alike); `text` gives each one's label and tooltip, and
   * compiles only in a panel whose controls have the terms' names.
   */
  protected phongSliders(
    text: Record<PhongTerm & ControlName<Panel>, [label: string, tooltip: string]>,
    values: Record<PhongTerm, number>,
    action: (changes: Partial<Record<PhongTerm, number>>) => LabAction,
  ): ControlPart[] {
    const [min, max] = LIMITS.coefficient;
    const terms = PHONG_TERMS.filter((term): term is PhongTerm & ControlName<Panel> => Object.hasOwn(text, term));
    return terms.map((term) =>
      this.slider({ name: term, label: text[term][0], tooltip: text[term][1], min, max, step: 0.01 }, values[term], (value) => action({ [term]: value })),
    );
  }

  protected switch(text: ControlText<ControlName<Panel>>, checked: boolean, action: (checked: boolean) => LabAction): ControlPart {
    if (!this.shows(text.name)) return nothing;
    return html`<rt-switch
      name=${text.name}
      data-guide=${ifDefined(this.guideOf(text.name))}
      label=${text.label}
      tooltip=${text.tooltip}
      .checked=${checked}
      .error=${this.errors[text.name]}
      @change=${(event: CustomEvent<CheckedDetail>) => this.send(text.name, action(event.detail.checked))}
    ></rt-switch>`;
  }

  protected color(text: ControlText<ControlName<Panel>>, value: Color, action: (value: Color) => LabAction): ControlPart {
    if (!this.shows(text.name)) return nothing;
    const send = (event: CustomEvent<ValueDetail<Color>>) => this.send(text.name, action(event.detail.value), event.type === 'input');
    return html`<rt-color-field
      name=${text.name}
      data-guide=${ifDefined(this.guideOf(text.name))}
      label=${text.label}
      tooltip=${text.tooltip}
      .value=${value}
      .error=${this.errors[text.name]}
      @input=${send}
      @change=${send}
    ></rt-color-field>`;
  }

  protected choice<T extends string>(text: ControlText<ControlName<Panel>>, options: ChoiceOption[], value: T, action: (value: T) => LabAction): ControlPart {
    if (!this.shows(text.name)) return nothing;
    return html`<rt-choice
      name=${text.name}
      data-guide=${ifDefined(this.guideOf(text.name))}
      label=${text.label}
      tooltip=${text.tooltip}
      .options=${options}
      .value=${value}
      .error=${this.errors[text.name]}
      @change=${(event: CustomEvent<ValueDetail<string>>) => this.send(text.name, action(event.detail.value as T))}
    ></rt-choice>`;
  }

  protected vector<V extends number[]>(spec: VectorSpec<ControlName<Panel>>, value: V, action: (value: V) => LabAction): ControlPart {
    if (!this.shows(spec.name)) return nothing;
    return html`<rt-vector-field
      name=${spec.name}
      data-guide=${ifDefined(this.guideOf(spec.name))}
      label=${spec.label}
      tooltip=${spec.tooltip}
      .axes=${spec.axes ?? ['x', 'y', 'z']}
      .min=${spec.min}
      .max=${spec.max}
      .step=${spec.step}
      unit=${spec.unit ?? ''}
      ?whole=${spec.whole ?? false}
      .limitReason=${spec.limitReason ?? ''}
      .value=${value}
      .error=${this.errors[spec.name]}
      @change=${(event: CustomEvent<ValueDetail<number[]>>) => this.send(spec.name, action(event.detail.value as V))}
    ></rt-vector-field>`;
  }
}
