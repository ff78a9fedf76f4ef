import type { MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import type { Scene } from '../scene/scene.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import { DEFAULT_SEED } from './render-job.ts';
import type { RenderPool } from './render-pool.ts';
import type { ScreenRays } from './screen-rays.ts';

/**
 * Pixel traces requested from the worker before their answers are back. Enough to hide
 * the message round trip; few enough that when a newer scene arrives the worker finishes
 * at most this many pixels of the old one (it answers requests in order and cannot drop
 * them) before it loads the new scene.
 */
export const TRACES_IN_FLIGHT = 16;

/** What the tracer needs of a RenderPool (a test can pass a fake). */
export type ScreenTracePool = Pick<RenderPool, 'setScene' | 'tracePixel'>;

export type ScreenRaysListener = (rays: ScreenRays) => void;

/**
 * Traces every pixel of the camera's screen (camera.pixels) off the main thread whenever
 * the scene changes, latest wins: at once when idle; a newer scene drops the running trace
 * (its results are thrown away and its remaining pixels never requested: a generation
 * counter), except a trace that itself replaced a dropped one, which is kept to its end and
 * then the newest scene is traced. So a single step is drawn after one trace, and a drag
 * (a step per frame) draws a new screen after every second trace instead of none until it
 * pauses: the old 60 ms debounce kept a drag's steps waiting 0.8–1.6 s in the benchmark.
 * The last value is always traced. Each finished
 * screen is published to the subscribers as ScreenRays, with the seed the render window
 * uses, so the trees match the rendered image.
 *
 * The pool is the caller's: give the tracer its own (one worker is enough, e.g.
 * `createBrowserRenderPool(1)`), so traces never wait behind a full render's tiles, and
 * dispose it after the tracer.
 */
export class ScreenTracer {
  /** Told when a screen cannot be traced (a model fails to load, a worker dies); default: the console. */
  onError: (error: Error) => void = (error) => console.error(error);
  private scene: Scene | null = null;
  /** The newest scene, not traced yet. */
  private pending: Scene | null = null;
  /** The trace under way; `kept` when it replaced a dropped trace (it is not dropped in turn). */
  private running: { kept: boolean } | null = null;
  private generation = 0;
  private latest: ScreenRays | null = null;
  private readonly listeners = new Set<ScreenRaysListener>();
  private disposed = false;

  constructor(
    private readonly pool: ScreenTracePool,
    private readonly loadMeshes: (names: string[]) => Promise<MeshLibrary>,
  ) {}

  /** The last published screen, or null before the first. */
  get rays(): ScreenRays | null {
    return this.latest;
  }

  /** Traces `scene` now, or after a kept running trace unless a newer one arrives first; the same object again is ignored. */
  update(scene: Scene): void {
    if (this.disposed || scene === this.scene) return;
    this.scene = scene;
    this.pending = scene;
    this.startPending();
  }

  /**
   * Pixel (x, y)'s tree with every hit's shading terms (the ray debugger), in the scene last
   * sent to the pool, so with the rays of the screen published for it (the seed is the same).
   */
  traceWithTerms(x: number, y: number): Promise<PixelTrace> {
    if (this.disposed || !this.latest) return Promise.reject(new Error('the camera’s screen has not been traced yet'));
    return this.pool.tracePixel(x, y, DEFAULT_SEED, true);
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
    this.generation++;
    this.running = null;
    this.pending = null;
    this.listeners.clear();
  }

  /** Starts the pending scene, dropping the running trace unless that one is kept (its end comes back here). */
  private startPending(): void {
    const scene = this.pending;
    if (!scene || this.disposed || this.running?.kept) return;
    this.pending = null;
    // A new generation stops a running trace's lanes; the trace that replaces it is kept.
    const run = { kept: this.running !== null };
    const generation = ++this.generation;
    this.running = run;
    void this.trace(scene, generation).finally(() => {
      if (this.running !== run) return;
      this.running = null;
      this.startPending();
    });
  }

  private async trace(scene: Scene, generation: number): Promise<void> {
    const current = () => generation === this.generation;
    let rays: ScreenRays;
    try {
      const meshes = await this.loadMeshes(meshNamesInScene(scene));
      if (!current()) return;
      this.pool.setScene(scene, meshes);
      const [columns, rows] = scene.camera.pixels;
      const traces = new Array<PixelTrace>(columns * rows);
      let next = 0;
      let failed = false;
      // TRACES_IN_FLIGHT lanes, each requesting the next pixel when its last one is back.
      const lane = async () => {
        while (next < traces.length && current() && !failed) {
          const index = next++;
          try {
            traces[index] = await this.pool.tracePixel(index % columns, Math.floor(index / columns), DEFAULT_SEED);
          } catch (error) {
            failed = true;
            throw error;
          }
        }
      };
      await Promise.all(Array.from({ length: Math.min(TRACES_IN_FLIGHT, traces.length) }, lane));
      if (!current()) return;
      rays = { columns, rows, traces };
    } catch (error) {
      // Not for a scene already replaced: a newer one is waiting or tracing.
      if (current() && this.pending === null) this.reportError(error);
      return;
    }
    this.latest = rays;
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
