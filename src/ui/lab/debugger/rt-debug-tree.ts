import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { styleMap } from 'lit/directives/style-map.js';
import { lightRayShare, type DebugProgram, type DebugStep } from '../../../debugger/debug-steps.ts';
import type { Quantization } from '../../../tracer/quantize.ts';
import { PLAIN_QUANTIZATION, pixelBytes } from '../../../tracer/quantize.ts';
import type { Color, Scene } from '../../../scene/scene.ts';
import { colorToHex } from '../../controls/color-hex.ts';
import { colorText } from './debug-numbers.ts';
import { shareText, treeLabel } from './debugger-text.ts';
import { revealRow } from './reveal-row.ts';
import { scrollCue } from './scroll-cue.ts';

/** Rows drawn at most: the steps before them are summed up in one line (a glossy pixel has thousands). */
const ROWS_SHOWN = 200;

/** Each level of the tree is indented this much, with a guide line per level. */
const INDENT_PX = 12;

/**
 * @summary The pixel's samples and rays as a tree, in the order the tracer makes them
 * (pixel sample → lens point → moment → hit → its light samples → its reflected and
 * refracted rays), one row per step up to the cursor, each ray with its share of the pixel;
 * under it, always in view, the pixel's running sum: the colour every step so far has added,
 * with its 8-bit value, which at the last step is the image's pixel.
 *
 * `program`, `index` (the cursor), `scene`; `quantization` (the image's encoding and dithering).
 * Rows carry `data-level`; the sum carries `data-sum` (r g b) for tests.
 */
export class RtDebugTree extends LocalizedElement {
  static override properties = {
    program: { attribute: false },
    index: { type: Number },
    scene: { attribute: false },
    quantization: { attribute: false },
  };

  static override styles = css`
    :host {
      display: flex;
      flex-direction: column;
      min-height: 0;
      font-size: 0.76rem;
    }
    h3 {
      margin: 0 0 2px;
      font-size: 0.8rem;
      display: flex;
      justify-content: space-between;
      gap: 8px;
    }
    h3 span {
      color: var(--rt-muted);
      font-weight: 400;
    }
    ol {
      flex: 1;
      min-height: 0;
      overflow-y: auto;
      list-style: none;
      margin: 0;
      padding: 0;
      border: 1px solid var(--rt-border);
      border-radius: 6px;
      --cue-bg: var(--rt-bg);
      ${scrollCue}
    }
    ol:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: -3px;
    }
    li {
      display: flex;
      align-items: stretch;
      gap: 4px;
      padding-right: 6px;
      line-height: 1.45;
      color: var(--rt-muted);
    }
    li[aria-current='step'] {
      background: var(--rt-accent-soft);
      color: var(--rt-text);
      font-weight: 600;
    }
    .indent {
      flex: none;
      /* One guide line per level: the nesting stays visible as rows scroll. */
      background: repeating-linear-gradient(to right, transparent 0 5px, var(--rt-border) 5px 6px, transparent 6px ${INDENT_PX}px);
    }
    .label {
      flex: 1;
      min-width: 0;
      overflow-wrap: anywhere;
    }
    .share {
      flex: none;
      font-variant-numeric: tabular-nums;
    }
    .earlier {
      padding-left: 6px;
      font-style: italic;
    }
    .running {
      margin-top: 4px;
      display: grid;
      grid-template-columns: 1.2em minmax(0, 1fr) auto;
      align-items: center;
      gap: 0 6px;
      font-weight: 600;
    }
    .running .swatch {
      grid-row: span 2;
      width: 1.2em;
      height: 1.2em;
      border-radius: 3px;
      border: 1px solid var(--rt-border);
    }
    .value {
      font-variant-numeric: tabular-nums;
      text-align: right;
    }
    .note {
      grid-column: 2 / -1;
      color: var(--rt-muted);
      font-weight: 400;
      font-size: 0.72rem;
    }
  `;

  declare program: DebugProgram | null;
  declare index: number;
  declare scene: Scene | null;
  declare quantization: Quantization;

  constructor() {
    super();
    this.program = null;
    this.index = 0;
    this.scene = null;
    this.quantization = PLAIN_QUANTIZATION;
  }

  protected override updated(changed: PropertyValues<this>): void {
    // The current row stays in view as the tree grows (the list scrolls, the sum below it does not).
    const list = this.renderRoot.querySelector('ol');
    if ((changed.has('index') || changed.has('program')) && list) revealRow(list, list.querySelector('[aria-current="step"]'));
  }

  override render() {
    const program = this.program;
    const scene = this.scene;
    if (!program || !scene) return nothing;
    const first = Math.max(0, this.index + 1 - ROWS_SHOWN);
    const rows = program.steps.slice(first, this.index + 1);
    return html`
      <h3>${msg('The pixel’s rays')}<span>${msg('share of the pixel')}</span></h3>
      <!-- Focusable: it scrolls, and a keyboard must be able to scroll it too (WCAG 2.1.1). -->
      <ol tabindex="0" aria-label=${msg('The pixel’s rays as a tree, up to this step')}>
        ${first > 0 ? html`<li class="earlier">${msg(str`… ${first} earlier steps`)}</li>` : nothing}
        ${rows.map((step, offset) => this.renderRow(step, first + offset, scene))}
      </ol>
      ${this.renderSum(program.steps[this.index], program)}
    `;
  }

  private renderRow(step: DebugStep, index: number, scene: Scene) {
    const current = index === this.index;
    // A ray's share; a light sample stands for 1/n² of its light at its hit.
    const rayShare = step.kind === 'sample' || step.kind === 'lens' || step.kind === 'cast' ? step.share : step.kind === 'light' ? lightRayShare(step) : null;
    const label = treeLabel(step, scene);
    return html`<li data-level=${step.level} data-kind=${step.kind} aria-current=${current ? 'step' : 'false'}>
      <span class="indent" style=${styleMap({ width: `${step.level * INDENT_PX}px` })}></span>
      <span class="label">${label}</span>
      ${rayShare !== null ? html`<span class="share">${shareText(rayShare)}</span>` : nothing}
    </li>`;
  }

  private renderSum(step: DebugStep, program: DebugProgram) {
    const [x, y] = program.trace.pixel;
    const bytes = (color: Color) => pixelBytes(color, x, y, this.quantization).join(', ');
    const adds = step.adds.some((value) => value !== 0);
    return html`<div class="running" data-sum=${step.sum.join(' ')}>
      <span class="swatch" aria-hidden="true" style=${styleMap({ background: colorToHex(step.sum) })}></span>
      <span>${msg('Pixel so far')}</span>
      <span class="value">${colorText(step.sum)}</span>
      <span class="note">${adds ? msg(str`this step adds ${colorText(step.adds)}`) : msg('this step adds nothing')} · ${msg(str`8-bit: ${bytes(step.sum)}`)}</span>
    </div>`;
  }
}

customElements.define('rt-debug-tree', RtDebugTree);

declare global {
  interface HTMLElementTagNameMap {
    'rt-debug-tree': RtDebugTree;
  }
}
