import type { MeshData, MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import type { Scene } from '../scene/scene.ts';
import type { LabPaths } from '../tracer/lab-paths.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import type { InlineScreenTracer } from './inline-screen-tracer.ts';
import { DEFAULT_SEED } from './render-job.ts';
import type { RenderPool } from './render-pool.ts';
import type { ScreenRays } from './screen-rays.ts';
import { settledSlices } from './settled-slices.ts';
import { countsEveryRay } from '../tracer/tree-budget.ts';
import type { RayBudget } from '../../workers/protocol.ts';

/**
 * Pixels traced per request: the screen goes in a few messages, not one per pixel (a 16×16
 * screen cost more in 256 round trips and their structured clones than in tracing).
 */
export const PIXELS_PER_REQUEST = 64;

/**
 * Requests posted before their answers are back: the worker goes on tracing while the main
 * thread is busy. On a CPU rasterizer the main thread waits 23–32 ms of each 50 ms frame
 * for the 3D view's read-back, and with 2 in flight a 16 × 16 screen's third block was asked
 * for only after that wait, so its rays often missed the next frame: a drag's p95 was
 * 138–140 ms with the page composited on the CPU, 94–98 ms with 4 (the whole of such a
 * screen asked for at once; docs/benchmark-log.md).
 */
export const REQUESTS_IN_FLIGHT = 4;

/**
 * How many times a screen trace asks again for a block whose request failed, while that
 * screen is still the newest (no other scene or budget came since). The pool fails a worker's
 * requests when it replaces the worker, dead or silent past its deadline (render-pool.ts);
 * under load a budgeted block once outlasted that deadline, and the view kept its thinned
 * screen for good (docs/benchmark-log.md, "The settled screen in slices"). Bounded, so a
 * scene that fails every worker is still reported, after at most this many tries more.
 */
export const TRACE_RETRIES = 2;

/** What the tracer needs of a RenderPool (a test can pass a fake). */
export type ScreenTracePool = Pick<RenderPool, 'setScene' | 'tracePixel' | 'tracePixels' | 'tracePaths'>;

export type ScreenRaysListener = (rays: ScreenRays) => void;

/**
 * Traces every pixel of the camera's screen (camera.pixels) whenever the scene changes,
 * latest wins, and publishes each finished screen to the subscribers as ScreenRays, with the
 * seed the render window uses, so the trees match the rendered image. The last value is
 * always traced.
 *
 * - A cheap screen is traced at once, inside `update` (given an inline tracer, see
 *   inline-screen-tracer.ts): its rays are drawn in the frame that shows the edit.
 * - Any other goes to the pool's worker: at once when idle, else right after the running
 *   trace, with the newest scene that arrived meanwhile (the ones in between are never
 *   traced). A running trace is never dropped: a step therefore waits at most one trace plus
 *   its own (≤ 2 traces), where dropping it for a newer scene and keeping only the
 *   replacement cost up to 2 traces plus the dropped one's lost pixels during a drag (p95
 *   131–195 ms against the ≤ 100 ms goal in the slider benchmark). A worker's screen that
 *   comes back after a newer scene was traced inline is not published.
 * - Except the full screen traced once a budget ends (setBudget): it goes in slices, one
 *   request at a time (settled-slices.ts), and a newer scene or budget stops it between two
 *   slices, unpublished; the edit that brought it turns the budget on again, so the full
 *   screen would only be thinned again. Finished, it is the screen traced in one go, to the bit.
 * - A block whose request fails (the pool replaced its worker) is asked again, TRACE_RETRIES
 *   times at most per screen, while that screen is the newest; then the failure is reported.
 *
 * The pool is the caller's: give the tracer its own (one worker is enough, e.g.
 * `createBrowserRenderPool(1)`), so traces never wait behind a full render's tiles, and
 * dispose it after the tracer.
 */
export class ScreenTracer {
  /** Told when a screen cannot be traced (a model fails to load, a worker dies); default: the console. */
  onError: (error: Error) => void = (error) => console.error(error);
  private scene: Scene | null = null;
  /** Scenes given to `update` so far: a trace is published only if it is of a newer one than the last published. */
  private updates = 0;
  private publishedUpdate = 0;
  /** The newest scene, not traced yet, and its number among the updates. */
  private pending: { scene: Scene; update: number } | null = null;
  private running = false;
  private latest: ScreenRays | null = null;
  /** The last published screen whose every ray was counted (not traced from one sample per pixel): what the settled screen's slices are sized by. */
  private counted: ScreenRays | null = null;
  /** Whether `latest` was traced inline (then the ray debugger's pixel is too). */
  private latestInline = false;
  private inline: InlineScreenTracer | null = null;
  /** Every model loaded so far, by name (a name always means the same model). */
  private readonly models = new Map<string, MeshData>();
  private readonly listeners = new Set<ScreenRaysListener>();
  private disposed = false;
  /** About how many rays a screen traced in the worker may send (setBudget), or null: all. */
  private budget: RayBudget | null = null;
  /** The budget the last trace in the worker was started with. */
  private startedWith: RayBudget | null = null;
  /** Whether a budget was ever set: a full trace is then the settled screen, made in slices. */
  private budgeted = false;

  constructor(
    private readonly pool: ScreenTracePool,
    private readonly loadMeshes: (names: string[]) => Promise<MeshLibrary>,
  ) {}

  /** The last published screen, or null before the first. */
  get rays(): ScreenRays | null {
    return this.latest;
  }

  /**
   * From now on traces the screens `inline` affords where `update` is called; the lab gives it
   * one when its 3D view loads (the tracer's code comes with the view's, not with the first page).
   */
  traceInline(inline: InlineScreenTracer): void {
    this.inline = inline;
    inline.prepare(this.models);
  }

  /**
   * Traces `scene`: now if it is cheap (see traceInline), else in the worker at once or after
   * the running trace unless a newer one arrives first. The same object again is ignored.
   */
  update(scene: Scene): void {
    if (this.disposed || scene === this.scene) return;
    this.scene = scene;
    const update = ++this.updates;
    if (this.inline?.affords(scene, this.models)) {
      this.pending = null;
      this.traceInlineNow(this.inline, scene, update);
      return;
    }
    this.pending = { scene, update };
    this.startPending();
  }

  /**
   * From now on a screen traced in the worker sends about `budget.rays` of its rays, all of
   * pixel `budget.keepPixel`'s (tree-budget.ts; the colours stay the full trace's unless
   * `budget.oneSample`: then each other pixel is traced from one sample alone): its
   * trees are copied into the page's memory ray by ray, 0.3 s of the main thread for 27,784
   * rays on this project's machine, which held every slider step while the learner edited.
   * null: all rays again, and a screen traced with fewer is traced again in full.
   */
  setBudget(budget: RayBudget | null): void {
    if (sameBudget(budget, this.budget)) return;
    this.budget = budget;
    if (budget) this.budgeted = true;
    const scene = this.scene;
    if (!scene || this.disposed || this.startedWith === null || sameBudget(budget, this.startedWith)) return;
    this.pending = { scene, update: ++this.updates };
    this.startPending();
  }

  /**
   * Pixel (x, y)'s tree with every hit's shading terms (the ray debugger), in the scene of
   * the latest published screen, so with its rays (the seed is the same).
   */
  traceWithTerms(x: number, y: number): Promise<PixelTrace> {
    if (this.disposed || !this.latest) return Promise.reject(new Error('the camera’s screen has not been traced yet'));
    const inline = this.latestInline ? this.inline : null;
    // A promise's executor turns a throw into a rejection.
    if (inline) return new Promise((resolve) => resolve(inline.traceWithTerms(x, y)));
    return this.pool.tracePixel(x, y, DEFAULT_SEED, true);
  }

  /** Pixel (x, y)'s first `keep` paths in path mode (lab-paths.ts), in the scene of the latest published screen. */
  tracePaths(x: number, y: number, keep: number): Promise<LabPaths> {
    if (this.disposed || !this.latest) return Promise.reject(new Error('the camera’s screen has not been traced yet'));
    const inline = this.latestInline ? this.inline : null;
    if (inline) return new Promise((resolve) => resolve(inline.tracePaths(x, y, keep)));
    return this.pool.tracePaths(x, y, keep, DEFAULT_SEED);
  }

  /** Calls `listener` with every published screen, and at once with the last one if any. Returns the unsubscribe. */
  subscribe(listener: ScreenRaysListener): () => void {
    this.listeners.add(listener);
    if (this.latest) listener(this.latest);
    return () => this.listeners.delete(listener);
  }

  /** Stops tracing and publishing (the pool stays open: it is the caller's). */
  dispose(): void {
    this.disposed = true;
    this.pending = null;
    this.listeners.clear();
  }

  private traceInlineNow(inline: InlineScreenTracer, scene: Scene, update: number): void {
    // A cheap screen is sent whole: there is nothing to trace again when a budget ends.
    this.startedWith = null;
    let rays: ScreenRays;
    try {
      rays = inline.trace(scene, this.models);
    } catch (error) {
      this.reportError(error);
      return;
    }
    this.publish(rays, update, true);
  }

  /** Traces the pending scene in the worker unless a trace is running (its end comes back here). */
  private startPending(): void {
    const pending = this.pending;
    if (!pending || this.disposed || this.running) return;
    this.pending = null;
    this.running = true;
    void this.trace(pending.scene, pending.update).finally(() => {
      this.running = false;
      this.startPending();
    });
  }

  private async trace(scene: Scene, update: number): Promise<void> {
    let rays: ScreenRays;
    try {
      const meshes = await this.loadMeshes(meshNamesInScene(scene));
      if (this.disposed) return;
      for (const [name, mesh] of meshes) this.models.set(name, mesh);
      this.inline?.prepare(meshes);
      this.pool.setScene(scene, meshes);
      const [columns, rows] = scene.camera.pixels;
      const traces = new Array<PixelTrace>(columns * rows);
      const budget = (this.startedWith = this.budget);
      const settled = budget === null && this.budgeted;
      // Request sizes, in screen order: the settled screen's slices, or blocks of PIXELS_PER_REQUEST.
      const sizes = settled ? settledSlices(scene, this.counted, PIXELS_PER_REQUEST) : [];
      // Only the settled screen gives way, between slices, to what came after it.
      const overtaken = () => settled && this.pending !== null;
      let next = 0;
      let failed = false;
      let retriesLeft = TRACE_RETRIES;
      // Only while nothing newer waits: a newer scene or budget is traced instead.
      const mayRetry = () => retriesLeft > 0 && !failed && !this.disposed && update === this.updates;
      // REQUESTS_IN_FLIGHT lanes, each requesting the next block of pixels when its last one is back.
      const lane = async () => {
        while (next < traces.length && !this.disposed && !failed && !overtaken()) {
          const first = next;
          const count = Math.min(sizes.shift() ?? PIXELS_PER_REQUEST, traces.length - first);
          next += count;
          const share = budget && { ...budget, rays: Math.ceil((budget.rays * count) / traces.length) };
          for (;;) {
            try {
              const block = await this.pool.tracePixels(first, count, DEFAULT_SEED, share ?? undefined);
              for (let i = 0; i < count; i++) traces[first + i] = block[i];
              break;
            } catch (error) {
              if (!mayRetry()) {
                failed = true;
                throw error;
              }
              retriesLeft--; // the same block again, of the pool's replacement worker
            }
          }
        }
      };
      // A slice at a time: what overtakes the settled screen waits for one slice at most.
      const lanes = settled ? 1 : Math.min(REQUESTS_IN_FLIGHT, Math.ceil(traces.length / PIXELS_PER_REQUEST));
      await Promise.all(Array.from({ length: lanes }, lane));
      if (this.disposed || overtaken()) return;
      rays = { columns, rows, traces, scene };
    } catch (error) {
      // Not for a scene already replaced: a newer one is waiting or was traced.
      if (!this.disposed && update === this.updates) this.reportError(error);
      return;
    }
    this.publish(rays, update, false);
  }

  /** Gives `rays` to the subscribers, unless a newer update's rays went out already. */
  private publish(rays: ScreenRays, update: number, inline: boolean): void {
    if (this.disposed || update < this.publishedUpdate) return;
    this.publishedUpdate = update;
    this.latest = rays;
    if (countsEveryRay(rays.traces)) this.counted = rays;
    this.latestInline = inline;
    for (const listener of [...this.listeners]) {
      try {
        listener(rays);
      } catch (error) {
        this.reportError(error); // one failing subscriber must not starve the others
      }
    }
  }

  private reportError(error: unknown): void {
    this.onError(error instanceof Error ? error : new Error(String(error)));
  }
}

function sameBudget(a: RayBudget | null, b: RayBudget | null): boolean {
  return a === b || (a !== null && b !== null && a.rays === b.rays && a.keepPixel === b.keepPixel && a.oneSample === b.oneSample);
}
