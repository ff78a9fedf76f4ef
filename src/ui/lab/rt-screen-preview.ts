import { msg, str } from '@lit/localize';
import { css, html, type PropertyValues } from 'lit';
import { styleMap } from 'lit/directives/style-map.js';
import type { ScreenRays } from '../../render/screen-rays.ts';
import { colorToHex } from '../controls/color-hex.ts';
import { StorePanel } from './panels/store-panel.ts';
import { guideIds } from '../../quest/lab-controls.ts';

/** Arrow keys → the step they move the focused cell by, as [dx, dy]. */
const ARROWS: Readonly<Record<string, [number, number]>> = {
  ArrowLeft: [-1, 0],
  ArrowRight: [1, 0],
  ArrowUp: [0, -1],
  ArrowDown: [0, 1],
};

/**
 * The smallest a pixel's button gets (CSS px): a target a pupil hits at the first try on a
 * school laptop's touchpad (WCAG 2.2's 24 px minimum target size, plus the 1 px gaps).
 */
const MIN_CELL_PX = 26;

/**
 * @summary The camera's traced image, enlarged: one button per pixel of its small screen,
 * filled with the pixel's colour. Choosing a pixel shows only its rays; choosing it again
 * (or "Show all pixels") shows every pixel's rays again.
 *
 * Keyboard: Tab reaches the grid once (roving tabindex), the arrow keys move between
 * cells, Enter or Space chooses; while a pixel is chosen the arrows move the choice, so
 * one can step through the pixels' ray trees. The chosen cell has a two-tone outline and
 * is announced as pressed, so colour is not the only sign.
 *
 * Dispatches `pixel.selected` / `pixel.deselected` on `store`; shows `rays` (the screen
 * tracer's latest), and says "Updating…" while they are of an older screen size.
 */
export class RtScreenPreview extends StorePanel<'screen-preview'> {
  protected readonly controlPanel = 'screen-preview';

  static override properties = {
    ...StorePanel.properties,
    rays: { attribute: false },
    focusIndex: { state: true },
  };

  static override styles = [
    StorePanel.styles,
    css`
      /* When the view is short (200 % zoom, a phone) the host's height is capped
         (lab-compact.css.ts): then the grid scrolls and the caption stays under it, on
         screen, instead of being scrolled away below the last row. */
      :host {
        display: flex;
        flex-direction: column;
      }
      .grid {
        flex: 0 1 auto;
        min-height: 0;
        overflow: auto;
        display: grid;
        /* Rows as tall as their square cells, also when the grid is shorter: it scrolls. */
        grid-auto-rows: max-content;
        gap: 1px;
        max-width: 100%;
        padding: 1px;
        border-radius: 6px;
        background: var(--rt-border);
      }
      .grid.stale {
        opacity: 0.6;
      }
      .cell {
        min-width: 0;
        min-height: 0;
        height: auto;
        aspect-ratio: 1;
        padding: 0;
        border: 0;
        border-radius: 0;
      }
      .cell:hover:not([aria-pressed='true']) {
        outline: 2px solid var(--rt-text);
        outline-offset: -2px;
      }
      .cell[aria-pressed='true'] {
        position: relative;
        z-index: 1;
        outline: 3px solid var(--rt-accent);
        outline-offset: 0;
        box-shadow: 0 0 0 5px var(--rt-surface);
      }
      .cell:focus-visible {
        position: relative;
        z-index: 2;
        outline: 3px solid var(--rt-text);
        outline-offset: 1px;
      }
      /* The caption wraps inside the grid's width and never widens the card: a wider card
         would enlarge every cell, and choosing a pixel (a longer caption with its button)
         would grow the preview over the very rays it shows. */
      .caption {
        flex: none;
        contain: inline-size;
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        justify-content: space-between;
        gap: 8px;
        margin: 8px 0 0;
        color: var(--rt-muted);
      }
      .placeholder {
        margin: 0;
        padding: 16px 0;
        color: var(--rt-muted);
        text-align: center;
      }
    `,
  ];

  /** The traced screen to show (null before the first trace). */
  declare rays: ScreenRays | null;
  /** The cell that Tab reaches (roving tabindex). */
  declare private focusIndex: number;

  constructor() {
    super();
    this.rays = null;
    this.focusIndex = 0;
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    super.willUpdate(changed);
    const selected = this.state?.selectedPixel;
    const rays = this.rays;
    // The chosen pixel is where Tab lands; a smaller screen may leave the old focus outside.
    if (selected && rays && selected[0] < rays.columns && selected[1] < rays.rows) this.focusIndex = selected[1] * rays.columns + selected[0];
    if (rays && this.focusIndex >= rays.traces.length) this.focusIndex = 0;
  }

  override render() {
    const rays = this.rays;
    if (!rays || rays.traces.length === 0) return html`<p class="placeholder" role="status">${msg('Tracing the camera’s pixels…')}</p>`;
    const [columns, rows] = this.state?.scene.camera.pixels ?? [rays.columns, rays.rows];
    const stale = columns !== rays.columns || rows !== rays.rows;
    const selected = this.state?.selectedPixel ?? null;
    return html`
      <div
        class=${stale ? 'grid stale' : 'grid'}
        data-guide=${guideIds('screen-preview.grid', 'screen.grid')}
        role="group"
        aria-label=${msg(str`Camera image, ${rays.columns} × ${rays.rows} pixels`)}
        style=${styleMap({ gridTemplateColumns: `repeat(${rays.columns}, minmax(${MIN_CELL_PX}px, 1fr))` })}
        @keydown=${this.onKeyDown}
      >
        ${rays.traces.map((trace, index) => {
          const [x, y] = trace.pixel;
          const pressed = selected !== null && selected[0] === x && selected[1] === y;
          return html`<button
            class="cell"
            data-index=${index}
            data-guide=${`screen.pixel:${x},${y}`}
            tabindex=${index === this.focusIndex ? 0 : -1}
            aria-label=${msg(str`Pixel ${x}, ${y}`)}
            aria-pressed=${pressed ? 'true' : 'false'}
            title=${pressed ? msg(str`Pixel ${x}, ${y}: show all pixels’ rays again`) : msg(str`Pixel ${x}, ${y}: show only its rays`)}
            style=${styleMap({ background: colorToHex(trace.color) })}
            @click=${() => this.choose(index, !pressed)}
          ></button>`;
        })}
      </div>
      <p class="caption">
        <span role="status">${stale ? msg('Updating…') : selected ? msg(str`Showing the rays of pixel ${selected[0]}, ${selected[1]}`) : msg('Choose a pixel to see only its rays.')}</span>
        ${
          selected
            ? html`<button title=${msg('Show the rays of every pixel again')} @click=${() => this.send('pixel', { type: 'pixel.deselected' })}>
              ${msg('Show all pixels')}
            </button>`
            : ''
        }
      </p>
    `;
  }

  /** Selects (or, with `select` false, deselects) the pixel of cell `index`. */
  private choose(index: number, select: boolean): void {
    const trace = this.rays?.traces[index];
    if (!trace) return;
    this.focusIndex = index;
    this.send('pixel', select ? { type: 'pixel.selected', pixel: [trace.pixel[0], trace.pixel[1]] } : { type: 'pixel.deselected' });
  }

  private onKeyDown(event: KeyboardEvent): void {
    const step = ARROWS[event.key];
    const rays = this.rays;
    if (!step || !rays) return;
    event.preventDefault();
    const x = Math.min(rays.columns - 1, Math.max(0, (this.focusIndex % rays.columns) + step[0]));
    const y = Math.min(rays.rows - 1, Math.max(0, Math.floor(this.focusIndex / rays.columns) + step[1]));
    const index = y * rays.columns + x;
    if (this.state?.selectedPixel) this.choose(index, true);
    else this.focusIndex = index;
    void this.updateComplete.then(() => this.renderRoot.querySelector<HTMLButtonElement>(`[data-index="${index}"]`)?.focus());
  }
}

customElements.define('rt-screen-preview', RtScreenPreview);

declare global {
  interface HTMLElementTagNameMap {
    'rt-screen-preview': RtScreenPreview;
  }
}
