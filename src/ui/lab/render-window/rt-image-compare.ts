import { msg, str } from '@lit/localize';
import { html, nothing } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { createRef, ref } from 'lit/directives/ref.js';
import { styleMap } from 'lit/directives/style-map.js';
import {
  type CanvasView,
  canvasView,
  type CompareMode,
  fitLayout,
  type ImageLayout,
  type Rect,
  sameRect,
  sameView,
  type Size,
  enlargesFit,
  zoomInStep,
  zoomOutStep,
} from './image-zoom.ts';
import { FRAME_PADDING, imageCompareLayout } from './image-compare-layout.css.ts';
import { controlStyles } from './render-window-styles.ts';

/**
 * The raster picture's label: drawn as the 3D view is, by rasterization, with the view's own
 * multisampling (4 samples a pixel on a GPU, 1 on a computer without one, whose picture is
 * jagged). "Like a game engine" under a jagged picture said that games do not anti-alias.
 */
const RASTER_LABEL = () => msg('Rasterized, like the 3D view');

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
 * The images are the parent's canvases, slotted in; the viewer only sizes and arranges them,
 * so the parent keeps drawing into the same canvases. The raster canvas is stretched over
 * the image's box. The traced canvas covers only the part of the box on screen
 * (`tracedView`): zoomed into a 4096² image, a canvas of the image's size cost a page
 * composited on the CPU 200–260 ms for every frame it changed in.
 *
 * @slot traced - The ray traced image: a canvas showing `tracedView.window` of the image at `tracedView.full` canvas pixels.
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
 * Read-only: `scale` (screen pixels per image pixel), `shownSize` (each image's box on screen,
 * CSS pixels), `tracedView` (what the traced canvas is to show, image-zoom.ts's CanvasView).
 *
 * @fires view-change - `tracedView` changed (a zoom, a scroll, a resized window, another
 *   image size): the parent draws the traced canvas for the new view.
 */
export class RtImageCompare extends LocalizedElement {
  static override properties = {
    imageWidth: { type: Number },
    imageHeight: { type: Number },
    mode: {},
    zoom: {},
    position: { type: Number },
    note: {},
    frame: { state: true },
  };

  static override styles = [controlStyles, imageCompareLayout];

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
  /** The traced image's box element, and the part of it on screen (CSS pixels from its top left; null: not measured). */
  private readonly tracedBoxRef = createRef<HTMLElement>();
  private visible: Rect | null = null;
  /** The view last announced by view-change. */
  private announced: CanvasView | null = null;
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

  /** What the traced canvas is to show: the part of the image on screen, at one canvas pixel per device pixel at most. */
  get tracedView(): CanvasView {
    const shown = this.shownSize;
    return canvasView({ width: this.imageWidth, height: this.imageHeight }, shown, this.visible ?? { x: 0, y: 0, ...shown }, devicePixelRatio);
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
    const frame = this.frameRef.value;
    if (frame && this.keepCentre) {
      frame.scrollLeft = this.keepCentre.x * frame.scrollWidth - frame.clientWidth / 2;
      frame.scrollTop = this.keepCentre.y * frame.scrollHeight - frame.clientHeight / 2;
      this.keepCentre = null;
    }
    this.measureVisible();
    const view = this.tracedView;
    if (!sameView(view, this.announced)) {
      this.announced = view;
      this.dispatchEvent(new Event('view-change'));
    }
  }

  /**
   * Measures the part of the traced image's box inside the frame's visible area; when it
   * moved, draws the traced canvas's place again (an update, which announces the view).
   */
  private measureVisible(): void {
    const frame = this.frameRef.value;
    const box = this.tracedBoxRef.value;
    if (!frame || !box) return;
    const outer = frame.getBoundingClientRect();
    const inner = box.getBoundingClientRect();
    const [left, top] = [outer.left + frame.clientLeft, outer.top + frame.clientTop];
    const x = Math.max(inner.left, left);
    const y = Math.max(inner.top, top);
    const width = Math.min(inner.right, left + frame.clientWidth) - x;
    const height = Math.min(inner.bottom, top + frame.clientHeight) - y;
    if (width <= 0 || height <= 0) return; // hidden: keep the last
    const visible = { x: x - inner.left, y: y - inner.top, width, height };
    if (this.visible && sameRect(visible, this.visible)) return;
    this.visible = visible;
    this.requestUpdate();
  }

  private shownMode(): CompareMode {
    return this.note ? 'traced' : this.mode;
  }

  private currentLayout(): ImageLayout {
    const fit = this.fitted();
    return this.zoom === 'fit' ? fit : { scale: this.zoom, direction: fit.direction };
  }

  /** The layout that fits the image(s) in the frame ("Fit"). */
  private fitted(): ImageLayout {
    const image = { width: this.imageWidth, height: this.imageHeight };
    return this.frame ? fitLayout(this.frame, image, this.shownMode()) : { scale: 1, direction: 'row' };
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
        @scroll=${this.measureVisible}
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
      <button
        @click=${() => (this.zoom = 2)}
        aria-pressed=${this.zoom === 2}
        ?disabled=${!enlargesFit(2, this.fitted().scale)}
        title=${enlargesFit(2, this.fitted().scale) ? msg('Each image pixel as 2 × 2 screen pixels') : msg('Fit already shows this small image larger than 200 %')}
      >
        200 %
      </button>
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
    return html`<div class="image" style=${box} ${slot === 'traced' ? ref(this.tracedBoxRef) : nothing}>
      ${slot === 'traced' ? this.tracedWindow() : html`<slot name="raster"></slot>`}
      <span class="chip">${slot === 'traced' ? msg('Ray traced') : RASTER_LABEL()}</span>
    </div>`;
  }

  /** The traced canvas's place: the window of tracedView, in the box's CSS pixels. */
  private tracedWindow() {
    const { full, window } = this.tracedView;
    const { width, height } = this.shownSize;
    const [toCssX, toCssY] = [width / full.width, height / full.height];
    const place = styleMap({
      left: `${window.x * toCssX}px`,
      top: `${window.y * toCssY}px`,
      width: `${window.width * toCssX}px`,
      height: `${window.height * toCssY}px`,
    });
    return html`<div class="window" style=${place}><slot name="traced"></slot></div>`;
  }

  /** The raster image underneath, the ray traced one on top, cut off right of the divider. */
  private sliderImage(box: ReturnType<typeof styleMap>) {
    const percent = this.position * 100;
    return html`<div class="image" style=${box} ${ref(this.stackRef)} ${ref(this.tracedBoxRef)}>
      <div class="layer"><slot name="raster"></slot></div>
      <div class="layer" style=${styleMap({ clipPath: `inset(0 ${100 - percent}% 0 0)` })}>${this.tracedWindow()}</div>
      <span class="chip">${msg('Ray traced')}</span>
      <span class="chip right">${RASTER_LABEL()}</span>
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
