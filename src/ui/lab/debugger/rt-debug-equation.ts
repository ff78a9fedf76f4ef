import { msg, str } from '@lit/localize';
import { css, html, LitElement, nothing } from 'lit';
import { styleMap } from 'lit/directives/style-map.js';
import { toByte, type Equation, type EquationTerm, type Factor, type PixelAverage } from '../../../debugger/debug-equation.ts';
import { currentLocale } from '../../../i18n/locale.ts';
import { localNumbers } from '../../../i18n/number-format.ts';
import type { Color, Scene } from '../../../scene/scene.ts';
import { colorToHex } from '../../controls/color-hex.ts';
import { itemName, termName } from './debugger-text.ts';

const number = localNumbers({ minimumFractionDigits: 3, maximumFractionDigits: 3 });
const factorNumber = localNumbers({ maximumFractionDigits: 3 });

/** "(0.125, 0.500, 1.000)" in the reader's number format (Dutch writes "(0,125; 0,500; 1,000)"). */
export function colorText(color: Color): string {
  return `(${color.map((value) => number.format(value)).join(currentLocale() === 'nl' ? '; ' : ', ')})`;
}

function factorText(factor: Factor): string {
  const value = typeof factor.value === 'number' ? factorNumber.format(factor.value) : colorText(factor.value);
  return `${factor.symbol} ${value}`;
}

/** The average step's numbers, with the image's own pixel to compare (same value). */
export interface PixelSum extends PixelAverage {
  /** The pixel as the camera's traced image has it, or null while it is being traced. */
  image: Color | null;
}

/** The term-click event's detail. */
export type TermClickDetail = EquationTerm;

/**
 * @summary A hit's colour written out as the sum of its terms, each with its factors and a
 * swatch, the sum and what clamping makes of it; or, at the last step, the samples' colours
 * averaged into the pixel, next to the image's pixel. Terms that come from a ray are buttons:
 * clicking one (or Enter) highlights that ray in 3D.
 *
 * @event term-click - a term was chosen (detail: the EquationTerm)
 */
export class RtDebugEquation extends LitElement {
  static override properties = {
    equation: { attribute: false },
    average: { attribute: false },
    scene: { attribute: false },
    chosen: {},
  };

  static override styles = css`
    :host {
      display: block;
      font-size: 0.8rem;
    }
    h3 {
      margin: 0 0 4px;
      font-size: 0.85rem;
    }
    ul {
      list-style: none;
      margin: 0;
      padding: 0;
      display: grid;
      gap: 2px;
    }
    .term {
      box-sizing: border-box;
      display: grid;
      grid-template-columns: 1.4em minmax(0, 1fr) auto;
      align-items: center;
      gap: 2px 8px;
      width: 100%;
      padding: 3px 6px;
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
    button.term:focus-visible {
      outline: 3px solid var(--rt-focus);
      outline-offset: 1px;
    }
    .term[aria-pressed='true'] {
      border-color: var(--rt-accent);
      background: var(--rt-accent-soft);
    }
    .term.zero {
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
      font-size: 0.75rem;
    }
    .total {
      border-top: 1px solid var(--rt-border);
      margin-top: 4px;
      padding-top: 4px;
      font-weight: 600;
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

  override render() {
    if (this.average) return this.renderAverage(this.average);
    const equation = this.equation;
    if (!equation || !this.scene) return html`<p>${msg('The equation appears when a ray hits a surface.')}</p>`;
    const scene = this.scene;
    return html`
      <h3>${msg(str`Colour of the hit on ${itemName(scene, equation.hit.objectId)}`)}</h3>
      <ul>
        ${equation.terms.map((term) => html`<li>${this.renderTerm(term, scene)}</li>`)}
        <li>${this.row(msg('Sum of the terms'), equation.sum, equation.clamped ? msg('before clamping') : '', 'total')}</li>
        ${equation.clamped ? html`<li>${this.row(msg('Clamped to 0..1'), equation.color, '', 'total')}</li>` : nothing}
      </ul>
    `;
  }

  private renderTerm(term: EquationTerm, scene: Scene) {
    const name = termName(term.kind, itemName(scene, term.lightId));
    const zero = term.color.every((value) => value === 0);
    const factors = [
      ...(term.samples > 1 ? [msg(str`Σ over ${term.samples} samples; A, S, N·L, R·V are means`)] : []),
      term.factors.map(factorText).join(' · '),
    ].join(' — ');
    if (!term.ray) return this.row(name, term.color, factors, zero ? 'zero' : '');
    return html`<button
      class=${zero ? 'term zero' : 'term'}
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
    const count = average.samples.length;
    const bytes = (color: Color) => color.map(toByte).join(', ');
    return html`
      <h3>${count > 1 ? msg(str`The pixel: the average of its ${count} samples`) : msg('The pixel: its one sample')}</h3>
      <ul>
        ${average.samples.map((color, index) => html`<li>${this.row(msg(str`Sample ${index + 1}`), color, count > 1 ? msg(str`weight 1/${count}`) : '', '')}</li>`)}
        <li>${this.row(msg('Pixel colour'), average.color, msg(str`8-bit: ${bytes(average.color)}`), 'total')}</li>
        ${average.image
          ? html`<li>${this.row(msg('The image’s pixel'), average.image, msg(str`8-bit: ${bytes(average.image)}`), 'total')}</li>`
          : nothing}
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
