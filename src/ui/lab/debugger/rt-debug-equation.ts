import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { styleMap } from 'lit/directives/style-map.js';
import type { Equation, EquationTerm, Factor, PixelAverage } from '../../../debugger/debug-equation.ts';
import { localNumbers } from '../../../i18n/number-format.ts';
import type { Color, Scene } from '../../../scene/scene.ts';
import { pixelBytes, type Quantization } from '../../../tracer/quantize.ts';
import { colorToHex } from '../../controls/color-hex.ts';
import { colorText } from './debug-numbers.ts';
import { itemName, placeText, shareText, termName } from './debugger-text.ts';
import { revealRow } from './reveal-row.ts';
import { scrollCue } from './scroll-cue.ts';

const factorNumber = localNumbers({ maximumFractionDigits: 3 });

function factorText(factor: Factor): string {
  const value = typeof factor.value === 'number' ? factorNumber.format(factor.value) : colorText(factor.value);
  return `${factor.symbol} ${value}`;
}

/** The average step's numbers, with the image's own pixel to compare (same value). */
export interface PixelSum extends PixelAverage {
  /** The pixel as the camera's traced image has it, or null while it is being traced. */
  image: Color | null;
  /** Which pixel, and how the image turns its colour into bytes. */
  pixel: readonly [number, number];
  quantization: Quantization;
}

/** The term-click event's detail. */
export type TermClickDetail = EquationTerm;

/**
 * @summary A hit's colour written out as the sum of its terms, each with its factors and a
 * swatch, growing as the debugger steps (a light's terms sample by sample, a reflection ray
 * by ray), the sum and what clamping makes of it; or, at the last step, the rays' colours
 * times their shares added into the pixel, next to the image's pixel. The terms scroll; the
 * sum under them stays in view. Terms that come from a ray are buttons: clicking one (or
 * Enter) highlights that ray in 3D.
 *
 * @event term-click - a term was chosen (detail: the EquationTerm)
 */
export class RtDebugEquation extends LocalizedElement {
  static override properties = {
    equation: { attribute: false },
    average: { attribute: false },
    scene: { attribute: false },
    chosen: {},
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
    }
    ul {
      list-style: none;
      margin: 0;
      padding: 0;
      display: grid;
      align-content: start;
      gap: 1px;
    }
    .terms {
      flex: 1;
      min-height: 0;
      overflow-y: auto;
      --cue-bg: var(--rt-surface);
      ${scrollCue}
    }
    .term {
      box-sizing: border-box;
      display: grid;
      grid-template-columns: 1.2em minmax(0, 1fr) auto;
      align-items: center;
      gap: 0 6px;
      width: 100%;
      padding: 2px 4px;
      text-align: left;
      font: inherit;
      color: var(--rt-text);
      background: transparent;
      border: 1px solid transparent;
      border-radius: 6px;
    }
    button.term {
      cursor: pointer;
    }
    button.term:hover {
      border-color: var(--rt-accent);
    }
    .terms:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: -3px;
    }
    button.term:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 1px;
    }
    .term[aria-pressed='true'] {
      border-color: var(--rt-accent);
      background: var(--rt-accent-soft);
    }
    .term.zero,
    .term.pending {
      color: var(--rt-muted);
    }
    .swatch {
      width: 1.2em;
      height: 1.2em;
      border-radius: 3px;
      border: 1px solid var(--rt-border);
      grid-row: span 2;
    }
    .value {
      font-variant-numeric: tabular-nums;
      text-align: right;
    }
    .factors {
      grid-column: 2 / -1;
      color: var(--rt-muted);
      font-size: 0.7rem;
    }
    .total {
      font-weight: 600;
    }
    .sums {
      border-top: 1px solid var(--rt-border);
      margin-top: 2px;
      padding-top: 2px;
    }
  `;

  declare equation: Equation | null;
  declare average: PixelSum | null;
  declare scene: Scene | null;
  /** The id of the term whose ray is highlighted, if one was clicked. */
  declare chosen: string | null;

  constructor() {
    super();
    this.equation = null;
    this.average = null;
    this.scene = null;
    this.chosen = null;
  }

  protected override updated(changed: PropertyValues<this>): void {
    // The term this step grows (a light sample, a returned ray) may sit below the short list's
    // fold: it scrolls into view, as the tree keeps its current row in view.
    const before = changed.get('equation') as Equation | null | undefined;
    const now = this.equation;
    if (!before || !now || before.hit !== now.hit || this.average) return;
    // The last of them: a light sample grows its diffuse term and, just under it, its highlight.
    const grown = now.terms
      .filter((term) => {
        const old = before.terms.find((candidate) => candidate.id === term.id);
        return !old || old.rays.added !== term.rays.added;
      })
      .at(-1);
    const list = this.renderRoot.querySelector('ul.terms');
    if (grown && list) revealRow(list, list.querySelector(`[data-term-row="${CSS.escape(grown.id)}"]`));
  }

  override render() {
    if (this.average) return this.renderAverage(this.average);
    const equation = this.equation;
    if (!equation || !this.scene) return html`<p>${msg('The equation appears when a ray hits a surface.')}</p>`;
    const scene = this.scene;
    const done = equation.complete;
    return html`
      <h3>${msg(str`Colour of the hit on ${itemName(scene, equation.hit.objectId)}`)}</h3>
      <!-- Focusable: the terms scroll in a short dock, and a keyboard must be able to scroll them too (WCAG 2.1.1). -->
      <ul class="terms" tabindex="0" aria-label=${msg('Its terms')}>
        ${equation.terms.map((term) => html`<li data-term-row=${term.id}>${this.renderTerm(term, scene)}</li>`)}
      </ul>
      <ul class="sums">
        <li>${this.row(done ? msg('Sum of the terms') : msg('Sum so far'), equation.sum, done && equation.clamped ? msg('before clamping') : '', 'total')}</li>
        ${done && equation.clamped ? html`<li>${this.row(msg('Clamped to 0..1'), equation.color, '', 'total')}</li>` : nothing}
      </ul>
    `;
  }

  private renderTerm(term: EquationTerm, scene: Scene) {
    const name = termName(term.kind, itemName(scene, term.lightId));
    const { added, total } = term.rays;
    const pending = added < total;
    const zero = term.color.every((value) => value === 0);
    // While its rays are still being added, the term says how far it is; its factors (means over all of them) come once it is whole.
    const factors = pending
      ? total > 1
        ? msg(str`${added} of ${total} rays added`)
        : msg('its ray is not added yet')
      : [...(term.samples > 1 ? [msg(str`Σ over ${term.samples} samples; A, S, N·L, R·V are means`)] : []), term.factors.map(factorText).join(' · ')].join(
          ' — ',
        );
    const kind = pending ? 'pending' : zero ? 'zero' : '';
    if (!term.ray) return this.row(name, term.color, factors, kind);
    return html`<button
      class=${`term ${kind}`}
      data-term=${term.id}
      aria-pressed=${this.chosen === term.id ? 'true' : 'false'}
      title=${msg('Highlight the ray this term comes from')}
      @click=${() => this.dispatchEvent(new CustomEvent<TermClickDetail>('term-click', { detail: term, bubbles: true, composed: true }))}
    >
      ${this.cells(name, term.color, factors)}
    </button>`;
  }

  private row(name: string, color: Color, factors: string, kind: string) {
    return html`<div class=${`term ${kind}`}>${this.cells(name, color, factors)}</div>`;
  }

  private cells(name: string, color: Color, factors: string) {
    return html`<span class="swatch" aria-hidden="true" style=${styleMap({ background: colorToHex(color) })}></span>
      <span>${name}</span>
      <span class="value">${colorText(color)}</span>
      ${factors ? html`<span class="factors">${factors}</span>` : nothing}`;
  }

  private renderAverage(average: PixelSum) {
    const [x, y] = average.pixel;
    const bytes = (color: Color) => pixelBytes(color, x, y, average.quantization).join(', ');
    const heading =
      average.rays > 1 ? msg(str`The pixel: the sum of its ${average.rays} rays’ colours, each times its share`) : msg('The pixel: its one ray’s colour');
    return html`
      <h3>${heading}</h3>
      <ul class="terms" tabindex="0" aria-label=${msg('The pixel’s parts')}>
        ${average.parts.map(
          (part) =>
            html`<li>${this.row(part.place ? placeText(part.place) : msg('Primary ray'), part.ray.color, average.rays > 1 ? msg(str`share ${shareText(part.share)}`) : '', '')}</li>`,
        )}
      </ul>
      <ul class="sums">
        <li>${this.row(msg('Pixel colour'), average.color, msg(str`8-bit: ${bytes(average.color)}`), 'total')}</li>
        ${average.image ? html`<li>${this.row(msg('The image’s pixel'), average.image, msg(str`8-bit: ${bytes(average.image)}`), 'total')}</li>` : nothing}
      </ul>
    `;
  }
}

customElements.define('rt-debug-equation', RtDebugEquation);

declare global {
  interface HTMLElementTagNameMap {
    'rt-debug-equation': RtDebugEquation;
  }
}
