import { msg, str } from '@lit/localize';
import { html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../../controls/localized-element.ts';
import { createRef, ref } from 'lit/directives/ref.js';
import { renderImageData } from '../../../render/image-data.ts';
import type { RenderImage } from '../../../render/render-job.ts';
import type { RenderPool } from '../../../render/render-pool.ts';
import type { LabState } from '../../../lab-state/lab-state.ts';
import type { Store } from '../../../lab-state/store.ts';
import type { Scene } from '../../../scene/scene.ts';
import { shownName } from '../scene-names.ts';
import { FocusReturn } from '../../controls/focus-return.ts';
import { GuideHostController } from '../guide-host.ts';
import { consumeStore } from '../store-context.ts';
import { BandPainter } from './band-painter.ts';
import { canvasView } from './image-zoom.ts';
import { ContrastToggle } from './contrast-toggle.ts';
import { errorMessage, RenderJobController, type ShownRender } from './render-job-controller.ts';
import { formatCount, formatDuration, pathsOnShow, formatTimeLeft, progressFraction, progressText, raysPerSecond } from './render-figures.ts';
import { HeavyRenderCheck } from './heavy-render-check.ts';
import { renderWindowLayout } from './render-window-layout.css.ts';
import { controlStyles } from './render-window-styles.ts';
import { pngFileName, savePng } from './save-png.ts';
import type { RtImageCompare } from './rt-image-compare.ts';
import '../../controls/rt-load-problem.ts';
import { paintRasterPicture, type RasterSnapshot, readBackOrWait, takeRasterPicture } from './raster-picture.ts';
import { guideIds } from '../../../quest/lab-controls.ts';

/**
 * @summary The render window: the full image ray traced by the worker pool, with a progressive
 * preview, progress, cancel, time and rays per second, zoom, Save as PNG and a comparison with
 * the raster view from the same camera.
 *
 * Only the Render button (or Enter on the window) starts a render; when the scene changes
 * after it, the window says so and offers to render again.
 *
 * Properties:
 * - `store` (Store, from the lab's context unless set): the lab state; renders `state.scene` at `settings.imageSize` and
 *   dispatches render.started, render.finished {ms}, render.cancelled and render.saved.
 * - `pool` (RenderPool): the app's worker pool (not disposed by this element).
 * - `rasterSnapshot` (RasterSnapshot, optional): the raster picture, taken when a render
 *   starts; without it the comparison modes are hidden with a note.
 * - `open` (boolean, reflected): shown when set; opening focuses the Render button.
 *
 * Methods: `startRender()`, `cancelRender()`.
 *
 * Guide ids (lab-controls.ts): render.start, render.cancel, render.save, render.close,
 * render.contrast, and render.zoom / render.compare on the image.
 *
 * Keys: Enter (not on a control) renders, Escape closes, + − 0 zoom in, out, to fit, C stretches the contrast.
 *
 * @fires close - The user asked to close the window (close button or Escape); the parent
 *   removes `open` and returns focus where it was.
 */
export class RtRenderWindow extends LocalizedElement {
  static override properties = {
    store: { attribute: false },
    pool: { attribute: false },
    rasterSnapshot: { attribute: false },
    open: { type: Boolean, reflect: true },
    sceneChanged: { state: true },
    rasterNote: { state: true },
    saveError: { state: true },
  };

  static override styles = [controlStyles, renderWindowLayout];

  declare store: Store | undefined;
  declare pool: RenderPool | undefined;
  declare rasterSnapshot: RasterSnapshot | undefined;
  declare open: boolean;
  declare sceneChanged: boolean;
  /** Why the render on show has no raster picture to compare with ('' when it has one). */
  declare rasterNote: string;
  declare saveError: string;

  private readonly focusReturn = new FocusReturn();
  private readonly renderButton = createRef<HTMLButtonElement>();
  private readonly cancelButton = createRef<HTMLButtonElement>();
  private readonly compare = createRef<RtImageCompare>();
  /** The image viewer once its module (loaded after the first screen) has upgraded it; it then opens at 'fit'. */
  private get viewer(): RtImageCompare | undefined {
    return customElements.get('rt-image-compare') ? this.compare.value : undefined;
  }
  private readonly tracedCanvas = createRef<HTMLCanvasElement>();
  private readonly rasterCanvas = createRef<HTMLCanvasElement>();

  private readonly painter = new BandPainter(
    () => this.tracedCanvas.value,
    (image) => {
      const compare = this.viewer;
      if (compare?.imageWidth === image.width && compare.imageHeight === image.height) return compare.tracedView;
      // Not the viewer's image (yet): all of it, no larger than the viewer's box.
      const shown = compare?.shownSize ?? image;
      return canvasView(image, shown, { x: 0, y: 0, ...shown }, devicePixelRatio);
    },
  );
  /** How long a render will take here, and the question before a heavy one. */
  private readonly check = new HeavyRenderCheck(this);
  private readonly jobs = new RenderJobController(this, {
    paint: (image, quantization) => this.painter.paint(image, quantization),
    paintChanges: (image, changes, quantization) => this.painter.paintChanges(image, changes, quantization),
    started: (shown, isCurrent) => this.prepareStage(shown, isCurrent),
  });
  private readonly contrast = new ContrastToggle(
    this,
    () => {
      const { finished, shown } = this.jobs;
      return finished && shown ? { image: finished, quantization: shown.scene.settings } : null;
    },
    (range) => this.painter.setStretch(range),
  );
  private unsubscribe: (() => void) | null = null;
  private seenScene: Scene | null = null;
  /** Whether the last render was running, to move focus from Cancel to Render when it ends. */
  private wasRunning = false;

  constructor() {
    super();
    this.open = false;
    this.sceneChanged = false;
    this.rasterNote = '';
    this.saveError = '';
    this.addEventListener('keydown', (event) => this.onKeyDown(event));
    consumeStore(this, (store) => (this.store = store));
    new GuideHostController(this);
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
    this.painter.stop();
  }

  override willUpdate(changed: PropertyValues<this>): void {
    if (changed.has('store') && this.isConnected) this.listenToStore();
    if (changed.has('open') && this.open) this.focusReturn.remember();
  }

  override updated(changed: PropertyValues<this>): void {
    if (changed.has('open') && !this.open && changed.get('open')) this.focusReturn.restore(this);
    // Focus was on Cancel when the render ended: move it to Render rather than lose it.
    const ended = this.wasRunning && !this.jobs.running && this.shadowRoot?.activeElement === this.cancelButton.value;
    this.wasRunning = this.jobs.running;
    const opened = changed.has('open') && this.open;
    if (opened || ended) this.renderButton.value?.focus();
    if (opened) this.painter.warmUp();
  }

  /**
   * Renders the store's scene at its image size, replacing the image on show. A render
   * estimated on this machine at over a minute waits for the learner: lighter options, or
   * `force` (which skips the estimate; `expectedSeconds` is what the learner was promised).
   */
  async startRender(force = false, expectedSeconds: number | null = null): Promise<void> {
    if (!this.store || !this.pool) return;
    let expected = expectedSeconds;
    const scene = this.store.state.scene;
    if (force || !this.check.needsCheck(scene, this.pool)) this.check.settle();
    else {
      const decision = await this.check.mayStart(scene, this.pool);
      if (!decision.start) return;
      expected = decision.expectedSeconds;
    }
    this.sceneChanged = false;
    this.saveError = '';
    await this.jobs.start(this.store, this.pool);
    // How the promise came true corrects the next estimates.
    if (expected !== null && this.jobs.status.kind === 'finished') this.check.finished(expected, this.jobs.status.ms);
  }

  /** Stops the running render (its partial image stays on show). */
  cancelRender(): void {
    this.jobs.cancel(this.store);
  }

  /**
   * A render starts: the raster picture is taken now (same camera, same moment) and drawn once
   * the canvases exist. The workers start once it is read back (readBackOrWait).
   */
  private async prepareStage({ width, height }: ShownRender, isCurrent: () => boolean): Promise<void> {
    const picture = takeRasterPicture(this.rasterSnapshot, width, height);
    this.rasterNote = 'note' in picture ? picture.note : '';
    await this.updateComplete; // the canvases exist from here on
    // Every new render opens whole: a zoom into the last image means nothing for this one.
    this.viewer?.zoomToFit();
    if (!('pixels' in picture)) return;
    void paintRasterPicture(picture.pixels, () => this.rasterCanvas.value, isCurrent).then((note) => {
      if (note && isCurrent()) this.rasterNote = note;
    });
    await readBackOrWait(picture.pixels);
  }

  /** What Save as PNG saves: the finished image, or a cancelled render's picture as it was on show. */
  private saveable(): { image: RenderImage; partial: boolean } | null {
    const { finished } = this.jobs;
    if (finished) return { image: finished, partial: false };
    const partial = this.jobs.partialPicture();
    return partial ? { image: partial, partial: true } : null;
  }

  private async save(): Promise<void> {
    const saveable = this.saveable();
    const shown = this.jobs.shown;
    if (!saveable || !shown) return;
    this.saveError = '';
    try {
      const pixels = renderImageData(saveable.image, shown.scene.settings);
      const name = pngFileName(shown.scene.name === undefined ? undefined : shownName(shown.scene.name, ''), shown.width, shown.height, saveable.partial);
      await savePng(pixels, name);
      this.store?.dispatch({ type: 'render.saved' });
    } catch (error) {
      this.saveError = msg(str`The image could not be saved: ${errorMessage(error)}`);
    }
  }

  private listenToStore(): void {
    this.unsubscribe?.();
    this.unsubscribe =
      this.store?.subscribe((state, action) => {
        if (action.type === 'scene.loaded') this.contrast.reset();
        this.onState(state);
      }) ?? null;
    if (this.store) this.onState(this.store.state);
  }

  private onState({ scene }: LabState): void {
    if (scene === this.seenScene) return;
    this.seenScene = scene;
    this.sceneChanged = this.jobs.isStale(this.store);
    this.requestUpdate(); // the header shows the size the next render will have
  }

  private onKeyDown(event: KeyboardEvent): void {
    if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    const target = event.composedPath()[0];
    const onControl = target instanceof HTMLButtonElement || target instanceof HTMLInputElement;
    const action: Record<string, (() => void) | undefined> = {
      Escape: () => this.requestClose(),
      Enter: onControl ? undefined : () => void this.startRender(),
      '+': () => this.viewer?.zoomIn(),
      '=': () => this.viewer?.zoomIn(),
      '-': () => this.viewer?.zoomOut(),
      '0': () => this.viewer?.zoomToFit(),
      c: () => this.contrast.toggle(),
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
        ${this.sizeLabel(width, height)} ${this.timeLeft()}
        <button data-guide=${guideIds('render.close')} @click=${this.requestClose} aria-label=${msg('Close the render window')} title=${msg('Close the render window (Esc)')}>✕</button>
      </header>
      <div class="actions">
        <button class="primary" data-guide=${guideIds('render.start')} ${ref(this.renderButton)} @click=${() => void this.startRender()} title=${msg('Ray trace the whole image with all workers (Enter)')}>
          ${msg('Render')}
        </button>
        <button data-guide=${guideIds('render.cancel')} ${ref(this.cancelButton)} @click=${this.cancelRender} ?disabled=${!this.jobs.running} title=${msg('Stop the render')}>${msg('Cancel')}</button>
        <div class="progress">${this.progress()}</div>
        <button data-guide=${guideIds('render.save')} @click=${() => void this.save()} ?disabled=${!this.jobs.finished && !this.jobs.hasPartial} title=${msg('Save the rendered image as a PNG file, at its exact pixels')}>
          ${msg('Save as PNG')}
        </button>
      </div>
      ${
        this.check.heavy
          ? this.check.note(
              this.check.heavy,
              (changes, seconds) => this.useLighter(changes, seconds),
              (seconds) => void this.startRender(true, seconds),
            )
          : nothing
      }
      ${this.jobs.shown ? this.stage(this.jobs.shown) : html`<div class="placeholder" data-guide=${guideIds('render.zoom', 'render.compare')}>${msg(str`Press Render to ray trace the scene at ${width} × ${height} pixels.`)}</div>`}
      <footer>
        ${this.outcome()} ${this.saveError ? html`<p role="alert" class="error">${this.saveError}</p>` : nothing} ${this.staleNote()}
      </footer>
    `;
  }

  /**
   * The size of the image on show, never the next render's under an old image: a size typed
   * in the ray tracer panel after a render is named as the next render's until it is made.
   */
  private sizeLabel(width: number, height: number) {
    const shown = this.jobs.shown;
    if (!shown) {
      return html`<span class="size" data-testid="render-size" title=${msg('The size of the image the next render makes (set in the ray tracer panel)')}>${msg(str`${width} × ${height} pixels`)}</span>`;
    }
    const next = shown.width !== width || shown.height !== height ? msg(str`; the next render: ${width} × ${height}`) : '';
    return html`<span class="size" data-testid="render-size" title=${msg('The size of the image on show; a new size from the ray tracer panel applies to the next render')}>${msg(str`${shown.width} × ${shown.height} pixels`)}${next}</span>`;
  }

  /** The running render's time left at its pace so far, in the header (the progress row has no room at 1366 px). */
  private timeLeft() {
    const status = this.jobs.status;
    if (status.kind !== 'rendering' || status.secondsLeft === null) return nothing;
    return html`<span class="left" data-testid="render-time-left">${formatTimeLeft(status.secondsLeft)}</span>`;
  }

  private progress() {
    const status = this.jobs.status;
    const label = msg('Render progress');
    if (this.check.estimating) return html`<progress aria-label=${label}></progress><span class="phase">${msg('Estimating how long it takes…')}</span>`;
    switch (status.kind) {
      case 'starting':
        return html`<progress aria-label=${label}></progress><span class="phase">${msg('Starting…')}</span>`;
      case 'rendering':
        return html`<progress aria-label=${label} max="1" value=${progressFraction(status)}></progress>
          <span class="phase" data-testid="render-progress">${progressText(status)}</span>`;
      case 'finished':
        return html`<progress aria-label=${label} max="1" value="1"></progress><span class="phase">${msg('Done')}</span>`;
      default:
        return nothing;
    }
  }

  private stage({ width, height }: ShownRender) {
    return html`<rt-image-compare
      data-guide=${guideIds('render.zoom', 'render.compare')}
      ${ref(this.compare)}
      .imageWidth=${width}
      .imageHeight=${height}
      .note=${this.rasterNote}
      @view-change=${() => this.painter.reframe()}
    >
      <canvas slot="traced" ${ref(this.tracedCanvas)} role="img" aria-label=${msg('The ray traced image')}></canvas>
      ${this.contrast.control()}
      <canvas slot="raster" ${ref(this.rasterCanvas)} role="img" aria-label=${msg('The raster image from the same camera')}></canvas>
    </rt-image-compare>`;
  }

  /** How the last render ended, for the footer; announced to screen readers. */
  private outcome() {
    const status = this.jobs.status;
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
          ${this.jobs.hasPartial ? msg('The image on show is partial: the render stopped before every pixel had all its samples. Save as PNG saves it as shown.') : nothing}
          ${status.paths?.done ? pathsOnShow(status.paths) : nothing}
        </p>`;
      case 'failed':
        if (status.unloadable)
          return html`<rt-load-problem data-testid="render-status" .text=${msg('The render workers could not be loaded.')} .reason=${status.message}></rt-load-problem>`;
        return html`<p role="alert" class="error" data-testid="render-status">${msg(str`The render failed: ${status.message}`)}</p>
          <button @click=${() => void this.startRender()} title=${msg('Start the render again')}>${msg('Try again')}</button>`;
      default:
        return nothing;
    }
  }

  /** A lighter render the learner picked from the question: its time was shown, so it starts at once. */
  private useLighter(changes: Partial<Scene['settings']>, seconds: number): void {
    this.store?.dispatch({ type: 'settings.changed', changes });
    void this.startRender(true, seconds);
  }

  private staleNote() {
    if (!this.sceneChanged || this.jobs.running) return nothing;
    return html`<p class="stale" role="status">
      <span aria-hidden="true">⚠</span>${msg('The scene changed since this render.')}
      <button @click=${() => void this.startRender()} title=${msg('Render the changed scene')}>${msg('Render again')}</button>
    </p>`;
  }
}

customElements.define('rt-render-window', RtRenderWindow);

declare global {
  interface HTMLElementTagNameMap {
    'rt-render-window': RtRenderWindow;
  }
}
