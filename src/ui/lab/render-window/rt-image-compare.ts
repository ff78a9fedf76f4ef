import { msg, str } from '@lit/localize';
import { css, html, LitElement, nothing } from 'lit';
import { createRef, ref } from 'lit/directives/ref.js';
import { styleMap } from 'lit/directives/style-map.js';
import { type CompareMode, fitLayout, type ImageLayout, type Size, SIDE_BY_SIDE_GAP, zoomInStep, zoomOutStep } from './image-zoom.ts';
import { controlStyles } from './render-window-styles.ts';

/** Space kept free around the image(s) inside the frame, in CSS pixels. */
const FRAME_PADDING = 8;

/** Where the centre of the view was, as fractions of the content, to keep it there across a zoom. */
interface ViewCentre {
  x: number;
  y: number;
}

/**
 * @summary An image viewer for the render window: zoom (fit, 100 %, 200 %, in and out, the
 * image scrolls inside its frame when larger) and a comparison of the ray traced image with
 * the raster one: alone, side by side, or stacked with a draggable divider.
 *
 * The images are the parent's canvases, slotted in and stretched to the image's box on
 * screen; the viewer only sizes and arranges them, so the parent keeps drawing into the same
 * canvases, at whatever size it chooses (shownSize says how large they are shown).
 *
 * @slot traced - The ray traced image (imageWidth × imageHeight pixels, in a canvas of that size or smaller).
 * @slot raster - The raster image of the same camera, at the same size or smaller (it is scaled to fit).
 * @slot tools - More controls for the image, at the end of the toolbar.
 *
 * Properties:
 * - `imageWidth`, `imageHeight`: the images' size in pixels (default 1 × 1).
 * - `mode`: 'traced' (default), 'side-by-side' or 'slider'.
 * - `zoom`: 'fit' (default) or screen pixels per image pixel (1 = 100 %).
 * - `position`: the slider's divider, 0 (all raster) to 1 (all ray traced); default 0.5.
 * - `note`: when not empty, the comparison is unavailable; the note says why and only the
 *   ray traced image is shown.
 *
 * Methods: `zoomIn()`, `zoomOut()`, `zoomToFit()` (the window's + − 0 keys).
 * Read-only: `scale` (screen pixels per image pixel), `shownSize` (each image's box on screen, CSS pixels).
 *
 * @fires shown-size-change - `shownSize` changed (a zoom, a resized window, another image
 *   size): the parent may draw its canvases at the new size.
 */
export class RtImageCompare extends LitElement {
  static override properties = {
    imageWidth: { type: Number },
    imageHeight: { type: Number },
    mode: {},
    zoom: {},
    position: { type: Number },
    note: {},
    frame: { state: true },
  };

  static override styles = [
    controlStyles,
    css`
      :host {
        display: flex;
        flex-direction: column;
        min-height: 0;
        gap: 8px;
      }
      .toolbar {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 8px 20px;
      }
      .readout {
        min-width: 4.5em;
        font-variant-numeric: tabular-nums;
        color: var(--rt-muted);
      }
      .note {
        margin: 0;
        color: var(--rt-muted);
        font-size: 0.9rem;
      }
      input[type='range'] {
        width: 140px;
        min-height: var(--rt-target);
        accent-color: var(--rt-accent);
      }
      .frame {
        flex: 1;
        min-height: 0;
        display: flex;
        overflow: auto;
        border-radius: 8px;
        background: color-mix(in srgb, var(--rt-text) 8%, var(--rt-bg));
      }
      .frame.fit {
        overflow: hidden;
      }
      /* Auto margins centre the content while it is smaller than the frame and fall to 0 when
         it is larger, so that it scrolls to every edge (centring with place-items would cut
         off its left and top). */
      .content {
        margin: auto;
        padding: ${FRAME_PADDING}px;
        display: flex;
        gap: ${SIDE_BY_SIDE_GAP}px;
      }
      .pixelated {
        image-rendering: pixelated;
      }
      .image {
        position: relative;
        flex: none;
        background: #000;
      }
      ::slotted(canvas) {
        display: block;
        width: 100%;
        height: 100%;
      }
      .layer {
        position: absolute;
        inset: 0;
      }
      .chip {
        position: absolute;
        top: 6px;
        left: 6px;
        max-width: calc(50% - 12px);
        padding: 2px 8px;
        border-radius: 6px;
        background: rgb(0 0 0 / 0.7);
        color: #fff;
        font-size: 0.8rem;
        pointer-events: none;
        z-index: 1; /* above the divider's line */
      }
      .chip.right {
        left: auto;
        right: 6px;
        text-align: right;
      }
      /* The divider: a thin line, with a 32 px wide strip around it to grab (touch). */
      .divider {
        position: absolute;
        top: 0;
        bottom: 0;
        width: var(--rt-target);
        transform: translateX(-50%);
        cursor: ew-resize;
        touch-action: none;
      }
      .divider::before {
        content: '';
        position: absolute;
        top: 0;
        bottom: 0;
        left: 15px;
        width: 2px;
        background: #fff;
        box-shadow: 0 0 0 1px rgb(0 0 0 / 0.5);
      }
      .grip {
        position: absolute;
        top: 50%;
        left: 0;
        width: var(--rt-target);
        height: var(--rt-target);
        transform: translateY(-50%);
        border-radius: 50%;
        background: #fff;
        color: #000;
        box-shadow: 0 1px 4px rgb(0 0 0 / 0.5);
        display: grid;
        place-items: center;
        font-size: 1rem;
      }
    `,
  ];

  declare imageWidth: number;
  declare imageHeight: number;
  declare mode: CompareMode;
  declare zoom: 'fit' | number;
  declare position: number;
  declare note: string;
  /** The frame's inner size, null until measured (or while hidden). */
  declare frame: Size | null;

  private readonly frameRef = createRef<HTMLElement>();
  private readonly stackRef = createRef<HTMLElement>();
  private readonly resizeObserver = new ResizeObserver(([entry]) => this.onFrameResized(entry.contentRect));
  /** The layout last drawn, and the view centre to restore after a zoom. */
  private layout: ImageLayout = { scale: 1, direction: 'row' };
  /** The box size last announced by shown-size-change. */
  private announced: Size | null = null;
  private keepCentre: ViewCentre | null = null;

  constructor() {
    super();
    this.imageWidth = 1;
    this.imageHeight = 1;
    this.mode = 'traced';
    this.zoom = 'fit';
    this.position = 0.5;
    this.note = '';
    this.frame = null;
  }

  /** Screen pixels per image pixel as shown now (the fitted scale when zoom is 'fit'). */
  get scale(): number {
    return this.currentLayout().scale;
  }

  /**
   * Each image's box on screen, in whole CSS pixels (rounded down, so that a fitted image
   * never overflows its frame by a fraction).
   */
  get shownSize(): Size {
    const { scale } = this.currentLayout();
    return { width: Math.floor(this.imageWidth * scale), height: Math.floor(this.imageHeight * scale) };
  }

  zoomIn(): void {
    this.zoom = zoomInStep(this.scale) ?? this.zoom;
  }

  zoomOut(): void {
    this.zoom = zoomOutStep(this.scale) ?? this.zoom;
  }

  zoomToFit(): void {
    this.zoom = 'fit';
  }

  override connectedCallback(): void {
    super.connectedCallback();
    if (this.frameRef.value) this.resizeObserver.observe(this.frameRef.value);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.resizeObserver.disconnect();
  }

  override firstUpdated(): void {
    const frame = this.frameRef.value;
    if (!frame) return;
    this.resizeObserver.observe(frame);
    // Measured now rather than at the observer's first report (after the next animation
    // frame's callbacks), so that the parent's first drawing knows the size it is shown at.
    this.onFrameResized({ width: frame.clientWidth, height: frame.clientHeight });
  }

  override willUpdate(): void {
    const next = this.currentLayout();
    const frame = this.frameRef.value;
    // Zooming keeps the middle of the view where it was, as image viewers do.
    if (frame && next.scale !== this.layout.scale && frame.scrollWidth > 0) {
      this.keepCentre = {
        x: (frame.scrollLeft + frame.clientWidth / 2) / frame.scrollWidth,
        y: (frame.scrollTop + frame.clientHeight / 2) / frame.scrollHeight,
      };
    }
    this.layout = next;
  }

  override updated(): void {
    const shown = this.shownSize;
    if (shown.width !== this.announced?.width || shown.height !== this.announced.height) {
      this.announced = shown;
      this.dispatchEvent(new Event('shown-size-change'));
    }
    const frame = this.frameRef.value;
    if (!frame || !this.keepCentre) return;
    frame.scrollLeft = this.keepCentre.x * frame.scrollWidth - frame.clientWidth / 2;
    frame.scrollTop = this.keepCentre.y * frame.scrollHeight - frame.clientHeight / 2;
    this.keepCentre = null;
  }

  private shownMode(): CompareMode {
    return this.note ? 'traced' : this.mode;
  }

  private currentLayout(): ImageLayout {
    const image = { width: this.imageWidth, height: this.imageHeight };
    const fit = this.frame ? fitLayout(this.frame, image, this.shownMode()) : { scale: 1, direction: 'row' as const };
    return this.zoom === 'fit' ? fit : { scale: this.zoom, direction: fit.direction };
  }

  private onFrameResized({ width, height }: Size): void {
    // A hidden window measures 0 × 0: keep the last size rather than fitting to nothing.
    if (width <= 0 || height <= 0) return;
    const inner = { width: width - 2 * FRAME_PADDING, height: height - 2 * FRAME_PADDING };
    if (inner.width !== this.frame?.width || inner.height !== this.frame.height) this.frame = inner;
  }

  override render() {
    const { scale, direction } = this.layout;
    const mode = this.shownMode();
    const { width, height } = this.shownSize;
    const box = styleMap({ width: `${width}px`, height: `${height}px` });
    return html`
      <div class="toolbar">
        ${this.zoomControls(scale)} ${this.note ? html`<p class="note">${this.note}</p>` : this.modeControls()}
        ${mode === 'slider' ? this.dividerControl() : nothing}
        <slot name="tools"></slot>
      </div>
      <div
        class="frame ${this.zoom === 'fit' ? 'fit' : ''}"
        ${ref(this.frameRef)}
        tabindex="0"
        role="group"
        aria-label=${msg('Image view: scroll with the arrow keys when zoomed in')}
      >
        <div class="content ${scale > 1 ? 'pixelated' : ''}" style=${styleMap({ flexDirection: direction })}>
          ${mode === 'traced' ? this.image('traced', box) : nothing}
          ${mode === 'side-by-side' ? [this.image('traced', box), this.image('raster', box)] : nothing}
          ${mode === 'slider' ? this.sliderImage(box) : nothing}
        </div>
      </div>
    `;
  }

  private zoomControls(scale: number) {
    return html`<div class="group" role="group" aria-label=${msg('Zoom')}>
      <span class="group-label">${msg('Zoom')}</span>
      <button @click=${() => this.zoomOut()} ?disabled=${zoomOutStep(scale) === null} aria-label=${msg('Zoom out')} title=${msg('Zoom out (−)')}>−</button>
      <button @click=${() => this.zoomToFit()} aria-pressed=${this.zoom === 'fit'} title=${msg('Fit the whole image in the window (0)')}>${msg('Fit')}</button>
      <button @click=${() => (this.zoom = 1)} aria-pressed=${this.zoom === 1} title=${msg('One image pixel per screen pixel')}>100 %</button>
      <button @click=${() => (this.zoom = 2)} aria-pressed=${this.zoom === 2} title=${msg('Each image pixel as 2 × 2 screen pixels')}>200 %</button>
      <button @click=${() => this.zoomIn()} ?disabled=${zoomInStep(scale) === null} aria-label=${msg('Zoom in')} title=${msg('Zoom in (+)')}>+</button>
      <span class="readout" aria-live="polite" title=${msg('The current zoom')}>${Math.round(scale * 100)} %</span>
    </div>`;
  }

  private modeControls() {
    const option = (mode: CompareMode, label: string, tooltip: string) =>
      html`<label class="toggle" title=${tooltip}>
        <input type="radio" name="mode" .checked=${this.mode === mode} @change=${() => (this.mode = mode)} /><span>${label}</span>
      </label>`;
    return html`<div class="group" role="radiogroup" aria-label=${msg('Compare with the raster view')}>
      <span class="group-label">${msg('Compare')}</span>
      ${option('traced', msg('Ray traced'), msg('Only the ray traced image'))}
      ${option('side-by-side', msg('Side by side'), msg('The ray traced and the raster image next to each other'))}
      ${option('slider', msg('Slider'), msg('Both images on top of each other, with a divider to drag'))}
    </div>`;
  }

  private dividerControl() {
    return html`<label class="group" title=${msg('Move the divider between the two images (arrow keys)')}>
      <span class="group-label">${msg('Divider')}</span>
      <input
        type="range"
        min="0"
        max="100"
        step="1"
        .value=${String(Math.round(this.position * 100))}
        @input=${(event: Event) => (this.position = Number((event.target as HTMLInputElement).value) / 100)}
        aria-valuetext=${msg(str`${Math.round(this.position * 100)} % ray traced`)}
      />
    </label>`;
  }

  private image(slot: 'traced' | 'raster', box: ReturnType<typeof styleMap>) {
    return html`<div class="image" style=${box}>
      <slot name=${slot}></slot>
      <span class="chip">${slot === 'traced' ? msg('Ray traced') : msg('Raster (like a game engine)')}</span>
    </div>`;
  }

  /** The raster image underneath, the ray traced one on top, cut off right of the divider. */
  private sliderImage(box: ReturnType<typeof styleMap>) {
    const percent = this.position * 100;
    return html`<div class="image" style=${box} ${ref(this.stackRef)}>
      <div class="layer"><slot name="raster"></slot></div>
      <div class="layer" style=${styleMap({ clipPath: `inset(0 ${100 - percent}% 0 0)` })}><slot name="traced"></slot></div>
      <span class="chip">${msg('Ray traced')}</span>
      <span class="chip right">${msg('Raster (like a game engine)')}</span>
      <div
        class="divider"
        style=${styleMap({ left: `${percent}%` })}
        title=${msg('Drag to move the divider')}
        @pointerdown=${this.onDividerDown}
        @pointermove=${this.onDividerMove}
      >
        <span class="grip" aria-hidden="true">⇔</span>
      </div>
    </div>`;
  }

  private onDividerDown(event: PointerEvent): void {
    (event.currentTarget as HTMLElement).setPointerCapture(event.pointerId);
    event.preventDefault(); // no text selection or scrolling while dragging
  }

  private onDividerMove(event: PointerEvent): void {
    const stack = this.stackRef.value;
    if (!stack || !(event.currentTarget as HTMLElement).hasPointerCapture(event.pointerId)) return;
    const box = stack.getBoundingClientRect();
    this.position = Math.min(1, Math.max(0, (event.clientX - box.left) / box.width));
  }
}

customElements.define('rt-image-compare', RtImageCompare);

declare global {
  interface HTMLElementTagNameMap {
    'rt-image-compare': RtImageCompare;
  }
}
