import { msg, str } from '@lit/localize';
import { css, html, LitElement, nothing, type PropertyValues } from 'lit';
import { createRef, ref } from 'lit/directives/ref.js';
import { renderImageData } from '../app/image-data.ts';
import { loadMeshes } from '../app/load-meshes-browser.ts';
import type { RenderImage, RenderJob, RenderProgress } from '../app/render-job.ts';
import type { RenderPool } from '../app/render-pool.ts';
import { pngFileName, savePng } from '../app/save-png.ts';
import type { AppState } from '../app/app-state.ts';
import type { Store } from '../app/store.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import type { Scene } from '../scene/scene.ts';
import { BandPainter } from './band-painter.ts';
import { countRays, formatCount, formatDuration, progressText, raysPerSecond } from './render-figures.ts';
import { controlStyles } from './render-window-styles.ts';
import type { RtImageCompare } from './rt-image-compare.ts';
import './rt-image-compare.ts';

/** The scene view's raster (three.js) picture from the ray tracer's camera, at this size. */
export type RasterSnapshot = (width: number, height: number) => ImageData;

type RenderStatus =
  | { kind: 'idle' }
  /** Models loading and the job starting, before the first progress. */
  | { kind: 'starting' }
  | ({ kind: 'rendering' } & RenderProgress)
  | { kind: 'finished'; ms: number; rays: number; workers: number }
  /** byUser: the Cancel button; otherwise the pool dropped the job (a new scene or render). */
  | { kind: 'cancelled'; byUser: boolean }
  | { kind: 'failed'; message: string };

/** The render on show: what was rendered, to tell when the scene has changed since. */
interface ShownRender {
  scene: Scene;
  json: string;
  width: number;
  height: number;
}

/**
 * @summary The render window: the full image ray traced by the worker pool, with a progressive
 * preview, progress, cancel, time and rays per second, zoom, Save as PNG and a comparison with
 * the raster view from the same camera.
 *
 * Only the Render button (or Enter on the window) starts a render; when the scene changes
 * after it, the window says so and offers to render again.
 *
 * Properties:
 * - `store` (Store): the app state; renders `state.scene` at `settings.imageSize` and
 *   dispatches render.started, render.finished {ms}, render.cancelled and render.saved.
 * - `pool` (RenderPool): the app's worker pool (not disposed by this element).
 * - `rasterSnapshot` (RasterSnapshot, optional): the raster picture, taken when a render
 *   starts; without it the comparison modes are hidden with a note.
 * - `open` (boolean, reflected): shown when set; opening focuses the Render button.
 *
 * Methods: `startRender()`, `cancelRender()`.
 *
 * Keys: Enter (not on a control) renders, Escape closes, + − 0 zoom in, out, to fit.
 *
 * @fires close - The user asked to close the window (close button or Escape); the parent
 *   removes `open` and returns focus where it was.
 */
export class RtRenderWindow extends LitElement {
  static override properties = {
    store: { attribute: false },
    pool: { attribute: false },
    rasterSnapshot: { attribute: false },
    open: { type: Boolean, reflect: true },
    status: { state: true },
    shown: { state: true },
    sceneChanged: { state: true },
    rasterNote: { state: true },
    saveError: { state: true },
  };

  static override styles = [
    controlStyles,
    css`
      :host {
        display: none;
        flex-direction: column;
        gap: 10px;
        box-sizing: border-box;
        min-height: 0;
        padding: 12px 16px;
        background: var(--rt-surface);
        color: var(--rt-text);
        font-family: var(--rt-font);
        border: 1px solid var(--rt-border);
        border-radius: var(--rt-radius);
        box-shadow: 0 12px 40px rgb(0 0 0 / 0.28);
      }
      :host([open]) {
        display: flex;
      }
      :host(:focus) {
        outline: none;
      }
      header,
      .actions,
      footer {
        display: flex;
        flex-wrap: wrap;
        align-items: center;
        gap: 8px 12px;
      }
      h2 {
        margin: 0;
        font-size: 1.15rem;
      }
      .size {
        flex: 1;
        color: var(--rt-muted);
        font-variant-numeric: tabular-nums;
      }
      .progress {
        flex: 1 1 240px;
        display: flex;
        align-items: center;
        gap: 8px;
      }
      progress {
        flex: 1;
        min-width: 80px;
        height: 10px;
        accent-color: var(--rt-accent);
      }
      .phase {
        min-width: 8.5em;
        font-variant-numeric: tabular-nums;
      }
      rt-image-compare,
      .placeholder {
        flex: 1;
        min-height: 0;
      }
      .placeholder {
        display: grid;
        place-items: center;
        padding: 16px;
        border-radius: 8px;
        background: color-mix(in srgb, var(--rt-text) 8%, var(--rt-bg));
        color: var(--rt-muted);
        text-align: center;
      }
      footer {
        min-height: 32px;
      }
      footer p {
        margin: 0;
      }
      .error {
        color: var(--rt-danger);
      }
      .stale {
        display: inline-flex;
        align-items: center;
        gap: 8px;
        padding: 2px 4px 2px 10px;
        border-radius: 8px;
        border: 1px solid color-mix(in srgb, #e8a317 60%, var(--rt-border));
        background: color-mix(in srgb, #e8a317 16%, var(--rt-surface));
      }
    `,
  ];

  declare store: Store | undefined;
  declare pool: RenderPool | undefined;
  declare rasterSnapshot: RasterSnapshot | undefined;
  declare open: boolean;
  declare status: RenderStatus;
  declare shown: ShownRender | null;
  declare sceneChanged: boolean;
  /** Why the render on show has no raster picture to compare with ('' when it has one). */
  declare rasterNote: string;
  declare saveError: string;

  private readonly renderButton = createRef<HTMLButtonElement>();
  private readonly cancelButton = createRef<HTMLButtonElement>();
  private readonly compare = createRef<RtImageCompare>();
  private readonly tracedCanvas = createRef<HTMLCanvasElement>();
  private readonly rasterCanvas = createRef<HTMLCanvasElement>();

  /** Each render's number; a late answer from an older one is ignored. */
  private renderId = 0;
  private job: RenderJob | null = null;
  /** The finished image, for Save as PNG. */
  private finished: RenderImage | null = null;
  private readonly painter = new BandPainter(() => this.tracedCanvas.value);
  private unsubscribe: (() => void) | null = null;
  private seenScene: Scene | null = null;
  /** Focus was on Cancel when the render ended: move it to Render rather than lose it. */
  private refocusRender = false;

  constructor() {
    super();
    this.open = false;
    this.status = { kind: 'idle' };
    this.shown = null;
    this.sceneChanged = false;
    this.rasterNote = '';
    this.saveError = '';
    this.addEventListener('keydown', (event) => this.onKeyDown(event));
  }

  override connectedCallback(): void {
    super.connectedCallback();
    // Focusable (not by Tab), so that a click on the window's background keeps its keys working.
    if (!this.hasAttribute('tabindex')) this.tabIndex = -1;
    this.listenToStore();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.unsubscribe?.();
    this.unsubscribe = null;
    if (this.running) this.stopJob();
    this.painter.stop();
  }

  override willUpdate(changed: PropertyValues<this>): void {
    if (changed.has('store') && this.isConnected) this.listenToStore();
  }

  override updated(changed: PropertyValues<this>): void {
    if ((changed.has('open') && this.open) || this.refocusRender) {
      this.refocusRender = false;
      this.renderButton.value?.focus();
    }
  }

  /** Renders the store's scene at its image size, replacing the image on show. */
  async startRender(): Promise<void> {
    const { store, pool } = this;
    if (!store || !pool) return;
    if (this.running) this.stopJob();
    const id = ++this.renderId;
    const scene = store.state.scene;
    const [width, height] = scene.settings.imageSize;
    this.shown = { scene, json: JSON.stringify(scene), width, height };
    this.sceneChanged = false;
    this.finished = null;
    this.saveError = '';
    this.status = { kind: 'starting' };
    store.dispatch({ type: 'render.started' });
    const raster = this.takeRasterSnapshot(width, height);
    await this.updateComplete; // the canvases exist from here on
    if (raster) void this.paintRaster(raster, id);
    const { dithering } = scene.settings;
    try {
      const meshes = await loadMeshes(meshNamesInScene(scene));
      if (id !== this.renderId) return;
      const job = pool.render(scene, meshes, {
        onPreview: (image) => {
          if (id === this.renderId) this.painter.paint(image, dithering);
        },
        onProgress: (progress) => {
          if (id !== this.renderId) return;
          this.status = { kind: 'rendering', ...progress };
          this.painter.paint(job.image, dithering);
        },
      });
      this.job = job;
      const result = await job.done;
      if (id !== this.renderId) return;
      this.endJob();
      if (result.cancelled) {
        this.status = { kind: 'cancelled', byUser: false };
        return;
      }
      this.finished = result;
      this.painter.paint(result, dithering);
      this.status = { kind: 'finished', ms: result.ms, rays: countRays(result.stats), workers: result.workers };
      store.dispatch({ type: 'render.finished', ms: result.ms });
    } catch (error) {
      if (id !== this.renderId) return;
      this.endJob();
      this.status = { kind: 'failed', message: errorMessage(error) };
    }
  }

  /** Stops the running render (its partial image stays on show). */
  cancelRender(): void {
    if (!this.running) return;
    this.stopJob();
    this.status = { kind: 'cancelled', byUser: true };
    this.store?.dispatch({ type: 'render.cancelled' });
  }

  private get running(): boolean {
    return this.status.kind === 'starting' || this.status.kind === 'rendering';
  }

  /** Drops the current render: its late answers are ignored from now on. */
  private stopJob(): void {
    this.renderId++;
    this.job?.cancel();
    this.endJob();
  }

  private endJob(): void {
    this.job = null;
    this.refocusRender = this.shadowRoot?.activeElement === this.cancelButton.value;
  }

  private takeRasterSnapshot(width: number, height: number): ImageData | null {
    this.rasterNote = '';
    if (!this.rasterSnapshot) {
      this.rasterNote = msg('Comparing with the raster view is not available here.');
      return null;
    }
    try {
      return this.rasterSnapshot(width, height);
    } catch (error) {
      this.rasterNote = msg(str`The raster view could not be captured (${errorMessage(error)}), so there is nothing to compare with.`);
      return null;
    }
  }

  /**
   * Draws the raster picture at its own size (CSS scales it on screen). Through an ImageBitmap,
   * which the browser makes off the main thread: putImageData of a 2048 × 1536 picture
   * blocked it for 50 ms.
   */
  private async paintRaster(pixels: ImageData, id: number): Promise<void> {
    let bitmap: ImageBitmap;
    try {
      bitmap = await createImageBitmap(pixels);
    } catch (error) {
      if (id === this.renderId) this.rasterNote = msg(str`The raster view could not be shown (${errorMessage(error)}).`);
      return;
    }
    const canvas = this.rasterCanvas.value;
    const context = canvas?.getContext('2d');
    if (id === this.renderId && canvas && context) {
      canvas.width = bitmap.width;
      canvas.height = bitmap.height;
      context.drawImage(bitmap, 0, 0);
    }
    bitmap.close();
  }

  private async save(): Promise<void> {
    const { finished, shown } = this;
    if (!finished || !shown) return;
    this.saveError = '';
    try {
      const pixels = renderImageData(finished, shown.scene.settings.dithering);
      await savePng(pixels, pngFileName(shown.scene.name, shown.width, shown.height));
      this.store?.dispatch({ type: 'render.saved' });
    } catch (error) {
      this.saveError = msg(str`The image could not be saved: ${errorMessage(error)}`);
    }
  }

  private listenToStore(): void {
    this.unsubscribe?.();
    this.unsubscribe = this.store?.subscribe((state) => this.onState(state)) ?? null;
    if (this.store) this.onState(this.store.state);
  }

  private onState({ scene }: AppState): void {
    if (scene === this.seenScene) return;
    this.seenScene = scene;
    // By content, not identity: every edit makes a new scene object, even one that changes a
    // value back. Scenes are a few kB of JSON, and this runs once per scene change.
    this.sceneChanged = this.shown !== null && JSON.stringify(scene) !== this.shown.json;
    this.requestUpdate(); // the header shows the size the next render will have
  }

  private onKeyDown(event: KeyboardEvent): void {
    if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    const target = event.composedPath()[0];
    const onControl = target instanceof HTMLButtonElement || target instanceof HTMLInputElement;
    const action: Record<string, (() => void) | undefined> = {
      Escape: () => this.requestClose(),
      Enter: onControl ? undefined : () => void this.startRender(),
      '+': () => this.compare.value?.zoomIn(),
      '=': () => this.compare.value?.zoomIn(),
      '-': () => this.compare.value?.zoomOut(),
      '0': () => this.compare.value?.zoomToFit(),
    };
    const run = action[event.key];
    if (!run) return;
    event.preventDefault();
    run();
  }

  private requestClose(): void {
    this.dispatchEvent(new Event('close', { bubbles: true, composed: true }));
  }

  override render() {
    const [width, height] = this.store?.state.scene.settings.imageSize ?? [0, 0];
    return html`
      <header>
        <h2>${msg('Ray traced image')}</h2>
        <span class="size" title=${msg('The size of the image the next render makes (set in the ray tracer panel)')}>
          ${msg(str`${width} × ${height} pixels`)}
        </span>
        <button data-command="render-close" @click=${this.requestClose} aria-label=${msg('Close the render window')} title=${msg('Close the render window (Esc)')}>✕</button>
      </header>
      <div class="actions">
        <button class="primary" ${ref(this.renderButton)} @click=${() => void this.startRender()} title=${msg('Ray trace the whole image with all workers (Enter)')}>
          ${msg('Render')}
        </button>
        <button ${ref(this.cancelButton)} @click=${this.cancelRender} ?disabled=${!this.running} title=${msg('Stop the render')}>${msg('Cancel')}</button>
        <div class="progress">${this.progress()}</div>
        <button @click=${() => void this.save()} ?disabled=${this.status.kind !== 'finished'} title=${msg('Save the rendered image as a PNG file, at its exact pixels')}>
          ${msg('Save as PNG')}
        </button>
      </div>
      ${this.shown ? this.stage(this.shown) : html`<div class="placeholder">${msg(str`Press Render to ray trace the scene at ${width} × ${height} pixels.`)}</div>`}
      <footer>
        ${this.outcome()} ${this.saveError ? html`<p role="alert" class="error">${this.saveError}</p>` : nothing} ${this.staleNote()}
      </footer>
    `;
  }

  private progress() {
    const status = this.status;
    const label = msg('Render progress');
    switch (status.kind) {
      case 'starting':
        return html`<progress aria-label=${label}></progress><span class="phase">${msg('Starting…')}</span>`;
      case 'rendering':
        return html`<progress aria-label=${label} max=${status.total} value=${status.done}></progress>
          <span class="phase">${progressText(status)}</span>`;
      case 'finished':
        return html`<progress aria-label=${label} max="1" value="1"></progress><span class="phase">${msg('Done')}</span>`;
      default:
        return nothing;
    }
  }

  private stage({ width, height }: ShownRender) {
    return html`<rt-image-compare ${ref(this.compare)} .imageWidth=${width} .imageHeight=${height} .note=${this.rasterNote}>
      <canvas slot="traced" ${ref(this.tracedCanvas)} role="img" aria-label=${msg('The ray traced image')}></canvas>
      <canvas slot="raster" ${ref(this.rasterCanvas)} role="img" aria-label=${msg('The raster image from the same camera')}></canvas>
    </rt-image-compare>`;
  }

  /** How the last render ended, for the footer; announced to screen readers. */
  private outcome() {
    const status = this.status;
    switch (status.kind) {
      case 'finished': {
        const workers = status.workers === 1 ? msg('1 worker') : msg(str`${status.workers} workers`);
        const rate = formatCount(raysPerSecond(status.rays, status.ms));
        return html`<p role="status" data-testid="render-status">
          ${msg(str`Done in ${formatDuration(status.ms)}: ${formatCount(status.rays)} rays, ${rate} rays per second, on ${workers}.`)}
        </p>`;
      }
      case 'cancelled':
        return html`<p role="status" data-testid="render-status">
          ${status.byUser ? msg('Render cancelled.') : msg('The render was stopped before it finished (the scene changed or another render started).')}
        </p>`;
      case 'failed':
        return html`<p role="alert" class="error" data-testid="render-status">${msg(str`The render failed: ${status.message}`)}</p>
          <button @click=${() => void this.startRender()} title=${msg('Start the render again')}>${msg('Try again')}</button>`;
      default:
        return nothing;
    }
  }

  private staleNote() {
    if (!this.sceneChanged || this.running) return nothing;
    return html`<p class="stale" role="status">
      <span aria-hidden="true">⚠</span>${msg('The scene changed since this render.')}
      <button @click=${() => void this.startRender()} title=${msg('Render the changed scene')}>${msg('Render again')}</button>
    </p>`;
  }
}


function errorMessage(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

customElements.define('rt-render-window', RtRenderWindow);

declare global {
  interface HTMLElementTagNameMap {
    'rt-render-window': RtRenderWindow;
  }
}
