import { msg, str } from '@lit/localize';
import { css, html, nothing } from 'lit';
import { styleMap } from 'lit/directives/style-map.js';
import type { Color } from '../../scene/scene.ts';
import type { RayHover } from '../../view/ray-layer.ts';
import { paletteNameFor, rayPalette } from '../../view/ray-palette.ts';
import { rayColorKeyName } from './ray-names.ts';
import { rayName, rayTargetText } from './traced-ray-text.ts';
import { itemName } from './scene-names.ts';
import { localNumbers } from '../../i18n/number-format.ts';
import { StorePanel } from './panels/store-panel.ts';

/** Gap between the pointer and the tooltip, in CSS pixels (clear of the cursor's arrow). */
const POINTER_GAP = 14;

const percentFormat = localNumbers({ maximumFractionDigits: 1 });

/**
 * A colour as the rendered image shows it: round(clamp(c) · 255) per channel with no gamma,
 * as the tracer's 8-bit quantization does (src/tracer/quantize.ts).
 */
export function colorBytes(color: Color): [number, number, number] {
  return color.map((c) => Math.round(Math.min(1, Math.max(0, c)) * 255)) as [number, number, number];
}

/** A share of the pixel as the tooltip writes it: "12.5 %" ("12,5 %" in Dutch), "< 0.1 %" for tiny non-zero shares. */
export function formatShare(share: number): string {
  if (share > 0 && share < 0.001) return msg('< 0.1 %');
  return msg(str`${percentFormat.format(share * 100)} %`);
}

/**
 * @summary What the pointer is over in the 3D view: the ray's kind (by name, with its
 * legend colour), its share of its pixel, the colour it brings back (swatch and RGB as in
 * the rendered image), its pixel, and what it hit; over a normal, only what it is.
 *
 * Shown at (`x`, `y`) (CSS pixels in its offset parent, e.g. the view's box) while `hover`
 * is set, flipped to the pointer's other side near the right and bottom edges; hidden when
 * it is null. It never takes the pointer (pointer-events: none). Reads `store` for the palette.
 */
export class RtRayTooltip extends StorePanel<'view'> {
  protected readonly controlPanel = 'view';
  static override properties = {
    ...StorePanel.properties,
    hover: { attribute: false },
    x: { type: Number },
    y: { type: Number },
  };

  static override styles = [
    StorePanel.styles,
    css`
      :host {
        position: absolute;
        left: 0;
        top: 0;
        z-index: 10;
        max-width: 20em;
        padding: 8px 12px;
        border: 1px solid var(--rt-border);
        border-radius: 8px;
        background: var(--rt-surface);
        box-shadow: 0 4px 16px rgb(0 0 0 / 0.25);
        pointer-events: none;
      }
      :host([hidden]) {
        display: none;
      }
      p {
        display: flex;
        align-items: center;
        gap: 8px;
        margin: 0;
      }
      p + p {
        margin-top: 4px;
      }
      .type {
        font-weight: 700;
      }
      .line {
        flex: none;
        width: 20px;
        height: 6px;
        border-radius: 3px;
      }
      .swatch {
        flex: none;
        width: 16px;
        height: 16px;
        border-radius: 4px;
      }
      .line,
      .swatch {
        box-shadow: 0 0 0 1px color-mix(in srgb, var(--rt-text) 35%, transparent);
      }
      .muted {
        color: var(--rt-muted);
      }
      .value {
        font-variant-numeric: tabular-nums;
      }
    `,
  ];

  /** The hovered ray, or null to hide. */
  declare hover: RayHover | null;
  /** Pointer position in CSS pixels relative to the offset parent. */
  declare x: number;
  declare y: number;

  constructor() {
    super();
    this.hover = null;
    this.x = 0;
    this.y = 0;
  }

  override updated(): void {
    this.hidden = this.hover === null;
    if (this.hidden) return;
    // Beside the pointer, on whichever side still has room in the parent.
    const parent = this.offsetParent;
    const width = this.offsetWidth;
    const height = this.offsetHeight;
    const left = parent && this.x + POINTER_GAP + width > parent.clientWidth ? this.x - POINTER_GAP - width : this.x + POINTER_GAP;
    const top = parent && this.y + POINTER_GAP + height > parent.clientHeight ? this.y - POINTER_GAP - height : this.y + POINTER_GAP;
    this.style.transform = `translate(${Math.max(0, left)}px, ${Math.max(0, top)}px)`;
  }

  override render() {
    const hover = this.hover;
    if (!hover) return nothing;
    const { node, drawnAs } = hover;
    const palette = rayPalette(paletteNameFor(this.state?.rays.colorBlindPalette ?? false));
    const [r, g, b] = colorBytes(hover.color);
    const [px, py] = hover.pixel;
    const scene = this.state?.scene;
    const target = rayTargetText(node, drawnAs, (id) => (id === null ? '' : scene ? itemName(scene, id) : id));
    const normal = drawnAs === 'normal';
    return html`
      <p class="type">
        <span class="line" style=${styleMap({ background: palette[drawnAs] })} aria-hidden="true"></span>
        ${normal ? rayColorKeyName('normal') : rayName(node)}
      </p>
      ${
        normal
          ? nothing
          : hover.path
            ? this.renderPathRay(hover)
            : html`<p>
              <span class="muted">${msg('Contribution')}</span>
              <span class="value" data-testid="ray-contribution">${formatShare(hover.contribution)}</span>
              <span class="muted">${msg(str`of pixel ${px}, ${py}`)}</span>
            </p>
            <p>
              <span class="muted">${msg('Brings back')}</span>
              <span class="swatch" style=${styleMap({ background: `rgb(${r}, ${g}, ${b})` })} aria-hidden="true"></span>
              <span class="value">${msg(str`RGB ${r}, ${g}, ${b}`)}</span>
            </p>`
      }
      ${target === null ? nothing : html`<p class="muted">${target}</p>`}
    `;
  }

  /**
   * A path's ray (path mode) is no share of the pixel (its width is the throughput, capped,
   * which the debugger's table gives exactly) and a bounce brings back no colour of its own:
   * only a light sample says what it added.
   */
  private renderPathRay(hover: RayHover) {
    if (hover.type !== 'light' && hover.type !== 'shadow') return nothing;
    const [r, g, b] = colorBytes(hover.color);
    return html`<p>
      <span class="muted">${msg('Added here')}</span>
      <span class="swatch" style=${styleMap({ background: `rgb(${r}, ${g}, ${b})` })} aria-hidden="true"></span>
      <span class="value">${msg(str`RGB ${r}, ${g}, ${b}`)}</span>
    </p>`;
  }
}

customElements.define('rt-ray-tooltip', RtRayTooltip);

declare global {
  interface HTMLElementTagNameMap {
    'rt-ray-tooltip': RtRayTooltip;
  }
}
