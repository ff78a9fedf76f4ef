import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { styleMap } from 'lit/directives/style-map.js';
import { paletteNameFor, RAY_COLOR_KEYS, RAY_DASHES, type RayColorKey, rayPalette } from '../../../view/ray-palette.ts';
import { rayColorKeyHint, rayColorKeyName } from '../ray-names.ts';
import { StorePanel } from './store-panel.ts';

/**
 * @summary The ray colours' legend: a swatch and the name of each kind of ray (never the
 * colour alone), in the palette the ray options choose (VRT's or the colour-blind-safe
 * one) and with the dash pattern the rays are drawn with; each entry's tooltip says what
 * that ray does.
 *
 * Reads `store` (rays.colorBlindPalette); changes nothing.
 */
export class RtRayLegend extends StorePanel {
  protected readonly controlPanel = 'rays';
  static override styles = [
    StorePanel.styles,
    css`
      ul {
        display: grid;
        grid-template-columns: repeat(auto-fill, minmax(9.5em, 1fr));
        gap: 4px 12px;
        margin: 0;
        padding: 0;
        list-style: none;
      }
      li {
        display: flex;
        align-items: center;
        gap: 8px;
        min-height: 24px;
        cursor: help;
      }
      .swatch {
        flex: none;
        width: 44px;
        height: 8px;
        border-radius: 4px;
        /* A thin outline keeps pale swatches (yellow, cyan) visible on a light background. */
        box-shadow: 0 0 0 1px color-mix(in srgb, var(--rt-text) 35%, transparent);
      }
    `,
  ];

  override render() {
    const palette = rayPalette(paletteNameFor(this.state?.rays.colorBlindPalette ?? false));
    return html`<ul aria-label=${msg('Ray colours')}>
      ${RAY_COLOR_KEYS.map(
        (key) => html`<li title=${rayColorKeyHint(key)} data-key=${key}>
          <span class="swatch" style=${styleMap({ background: swatch(palette[key], key) })} aria-hidden="true"></span>
          <span>${rayColorKeyName(key)}</span>
        </li>`,
      )}
    </ul>`;
  }
}

/** The swatch's paint: the ray's colour in its dashes (RAY_DASHES at 150 px per metre), or solid. */
function swatch(color: string, key: RayColorKey): string {
  const [dash, gap] = RAY_DASHES[key].map((metres) => metres * 150);
  return dash > 0 ? `repeating-linear-gradient(90deg, ${color} 0 ${dash}px, transparent ${dash}px ${dash + gap}px)` : color;
}

customElements.define('rt-ray-legend', RtRayLegend);

declare global {
  interface HTMLElementTagNameMap {
    'rt-ray-legend': RtRayLegend;
  }
}
