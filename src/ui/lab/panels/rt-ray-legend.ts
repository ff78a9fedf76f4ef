import { msg } from '@lit/localize';
import { css, html } from 'lit';
import { visuallyHiddenStyles } from '../../controls/visually-hidden.css.ts';
import { styleMap } from 'lit/directives/style-map.js';
import { FILLED_GAP_KEYS, GAP_FILL, legendKeys, paletteNameFor, RAY_DASHES, type RayColorKey, rayPalette, STOPPED_KEYS } from '../../../view/ray-palette.ts';
import { rayColorKeyHint, rayColorKeyName } from '../ray-names.ts';
import { StorePanel } from './store-panel.ts';
import { timeKey, timeKeyStyles } from './time-key.ts';
import { pathKey, pathKeyStyles } from './path-key.ts';
import { PATH_DASHES } from '../../../view/path-dashes.ts';

/**
 * @summary The ray colours' legend: a swatch and the name of each kind of ray (never the
 * colour alone), in the palette the ray options choose (VRT's or the colour-blind-safe
 * one) and with the dash pattern the rays are drawn with; each entry's tooltip says what
 * that ray does. The normal is an entry too; "direction to the light — not tested" only
 * while Shadows is off (legendKeys).
 *
 * While "Colour by time" is on, a key of the time colours follows (time-key.ts).
 *
 * In path mode with a pixel chosen, the swatches take the paths' patterns and a key of the
 * paths' marks follows (path-key.ts).
 *
 * Reads `store` (rays.colorBlindPalette, rays.colorByTime, scene.settings.shadows and
 * integrator, selectedPixel); changes nothing.
 */
export class RtRayLegend extends StorePanel<'rays'> {
  protected readonly controlPanel = 'rays';
  static override styles = [
    StorePanel.styles,
    // The dash between a name and its detail is read out; on screen the line break stands for it.
    visuallyHiddenStyles,
    timeKeyStyles,
    pathKeyStyles,
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
      /* A stopped ray ends in a bar across it, as its plate looks in the view from the side. */
      .swatch.stopped {
        position: relative;
      }
      .swatch.stopped::after {
        content: '';
        position: absolute;
        right: -2px;
        top: -4px;
        width: 3px;
        height: 16px;
        border-radius: 1px;
        background: currentColor;
      }
      .detail {
        display: block;
        font-size: 0.85em;
        color: var(--rt-muted);
      }
    `,
  ];

  override render() {
    const palette = rayPalette(paletteNameFor(this.state?.rays.colorBlindPalette ?? false));
    // Path mode draws a chosen pixel's sample paths, in their own patterns (path-dashes.ts).
    const paths = this.state?.scene.settings.integrator === 'path' && this.state.selectedPixel !== null;
    const dashes = paths ? PATH_DASHES : RAY_DASHES;
    return html`<ul aria-label=${msg('Ray colours')}>
      ${legendKeys(this.state?.scene.settings.shadows !== false).map(
        (key) => html`<li title=${rayColorKeyHint(key)} data-key=${key}>
          <span class=${STOPPED_KEYS.has(key) ? 'swatch stopped' : 'swatch'} style=${styleMap({ background: swatch(palette[key], key, dashes), color: palette[key] })} aria-hidden="true"></span>
          ${entryName(rayColorKeyName(key))}
        </li>`,
      )}
    </ul>
    ${timeKey(this.state?.rays.colorByTime ?? false)} ${pathKey(paths)}`;
  }
}

/**
 * A name as "kind — detail" ("Shadow ray — blocked") in two lines, the detail smaller below:
 * the legend over the view is a narrow column, and the kind is what the eye looks for.
 */
function entryName(name: string) {
  const at = name.indexOf(' — ');
  if (at < 0) return html`<span>${name}</span>`;
  return html`<span>${name.slice(0, at)}<span class="detail"><span class="visually-hidden"> — </span>${name.slice(at + 3)}</span></span>`;
}

/**
 * The swatch's paint: the ray's colour in its dashes (RAY_DASHES at 150 px per metre), their
 * gaps open or filled as the view draws them, or solid.
 */
function swatch(color: string, key: RayColorKey, dashes: typeof RAY_DASHES): string {
  const [dash, gap] = dashes[key].map((metres) => metres * 150);
  const between = FILLED_GAP_KEYS.has(key) ? GAP_FILL : 'transparent';
  const line = dash > 0 ? `repeating-linear-gradient(90deg, ${color} 0 ${dash}px, ${between} ${dash}px ${dash + gap}px)` : color;
  return line;
}

customElements.define('rt-ray-legend', RtRayLegend);

declare global {
  interface HTMLElementTagNameMap {
    'rt-ray-legend': RtRayLegend;
  }
}
