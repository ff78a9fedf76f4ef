import type { MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import type { Scene } from '../scene/scene.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import { DEFAULT_SEED } from './render-job.ts';
import type { RenderPool } from './render-pool.ts';
import type { ScreenRays } from './screen-rays.ts';

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
 * screen asked for at once; docs/benchmarks.md).
 */
export const REQUESTS_IN_FLIGHT = 4;

/** What the tracer needs of a RenderPool (a test can pass a fake). */
export type ScreenTracePool = Pick<RenderPool, 'setScene' | 'tracePixel' | 'tracePixels'>;

export type ScreenRaysListener = (rays: ScreenRays) => void;

/**
 * Traces every pixel of the camera's screen (camera.pixels) off the main thread whenever
 * the scene changes, latest wins: at once when idle, else right after the running trace,
 * with the newest scene that arrived meanwhile (the ones in between are never traced). A
 * running trace is never dropped: a step therefore waits at most one trace plus its own
 * (≤ 2 traces), where dropping it for a newer scene and keeping only the replacement cost up
 * to 2 traces plus the dropped one's lost pixels during a drag (p95 131–195 ms against
 * the ≤ 100 ms goal in the slider benchmark). The last value is always traced. Each finished
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
  private running = false;
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

  /** Traces `scene` now, or after the running trace unless a newer one arrives first; the same object again is ignored. */
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
    this.pending = null;
    this.listeners.clear();
  }

  /** Traces the pending scene unless a trace is running (its end comes back here). */
  private startPending(): void {
    const scene = this.pending;
    if (!scene || this.disposed || this.running) return;
    this.pending = null;
    this.running = true;
    void this.trace(scene).finally(() => {
      this.running = false;
      this.startPending();
    });
  }

  private async trace(scene: Scene): Promise<void> {
    let rays: ScreenRays;
    try {
      const meshes = await this.loadMeshes(meshNamesInScene(scene));
      if (this.disposed) return;
      this.pool.setScene(scene, meshes);
      const [columns, rows] = scene.camera.pixels;
      const traces = new Array<PixelTrace>(columns * rows);
      let next = 0;
      let failed = false;
      // REQUESTS_IN_FLIGHT lanes, each requesting the next block of pixels when its last one is back.
      const lane = async () => {
        while (next < traces.length && !this.disposed && !failed) {
          const first = next;
          const count = Math.min(PIXELS_PER_REQUEST, traces.length - first);
          next += count;
          try {
            const block = await this.pool.tracePixels(first, count, DEFAULT_SEED);
            for (let i = 0; i < count; i++) traces[first + i] = block[i];
          } catch (error) {
            failed = true;
            throw error;
          }
        }
      };
      await Promise.all(Array.from({ length: Math.min(REQUESTS_IN_FLIGHT, Math.ceil(traces.length / PIXELS_PER_REQUEST)) }, lane));
      if (this.disposed) return;
      rays = { columns, rows, traces, scene };
    } catch (error) {
      // Not for a scene already replaced: a newer one is waiting.
      if (!this.disposed && this.pending === null) this.reportError(error);
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
