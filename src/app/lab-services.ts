import { initialState, type LabState } from '../lab-state/lab-state.ts';
import { Store } from '../lab-state/store.ts';
import type { RenderPool } from '../render/render-pool.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import { ScreenTracer } from '../render/screen-tracer.ts';
import { defaultScene } from '../scene/scene-defaults.ts';
import type { MeshLoader } from '../view/scene-sync.ts';
import { BvhBoxes } from '../view/bvh-boxes.ts';
import type { LabView } from '../view/lab-view.ts';
import { RayPool, type RayPoolStats } from '../view/ray-pool.ts';

/** What the services draw into: the lab's three.js view. */
export type LabViewPort = Pick<LabView, 'setScreenRays' | 'setRayLayer' | 'setBvhLayer' | 'requestRender'>;

export interface LabServicesOptions {
  /** A render worker pool with `workers` workers (default: one per core). */
  createPool(workers?: number): RenderPool;
  loadMeshes: MeshLoader;
  /** A message for the learner: a refused change, rays that could not be traced. */
  report(text: string, tone: 'info' | 'error'): void;
  /** The words of a tracing failure (the UI translates them). */
  traceFailed(error: Error): string;
}

/**
 * The lab's services and how they are wired, apart from any page: the one store, the render
 * pool for full images, a one-worker pool and the screen tracer that traces the camera's
 * pixels, the ray pool that draws their rays and the BVH boxes.
 *
 * - A new scene is traced again (at once, or after the running trace; latest wins) and its boxes redrawn.
 * - New rays, ray options or a picked pixel redraw the rays; the view draws on demand.
 * - Listeners hear when the screen's rays change (the flat preview shows them).
 */
export class LabServices {
  /** The app's one source of truth. */
  readonly store = new Store(initialState(defaultScene()));
  readonly renderPool: RenderPool;
  readonly rayPool = new RayPool();
  /** The bounding boxes and BVH boxes of the acceleration levels, drawn in the 3D view. */
  readonly bvhBoxes: BvhBoxes;
  private readonly tracePool: RenderPool;
  private readonly tracer: ScreenTracer;
  private view: LabViewPort | null = null;
  /** The ray options and picked pixel the pool last drew with. */
  private drawnWith: Pick<LabState, 'rays' | 'selectedPixel'>;
  private readonly listeners = new Set<(rays: ScreenRays) => void>();
  private readonly cleanup: (() => void)[] = [];

  constructor(options: LabServicesOptions) {
    this.renderPool = options.createPool();
    this.tracePool = options.createPool(1);
    this.drawnWith = { rays: this.store.state.rays, selectedPixel: this.store.state.selectedPixel };
    this.bvhBoxes = new BvhBoxes(() => this.view?.requestRender(), options.loadMeshes);
    this.tracer = new ScreenTracer(this.tracePool, options.loadMeshes);
    this.tracer.onError = (error) => options.report(options.traceFailed(error), 'error');
    this.cleanup.push(
      this.tracer.subscribe((rays) => {
        this.view?.setScreenRays(rays);
        this.redrawRays();
        for (const listener of [...this.listeners]) listener(rays);
      }),
      this.store.subscribe((state, _action, error) => {
        if (error) options.report(error, 'error');
        this.tracer.update(state.scene);
        this.bvhBoxes.update(state);
        // Rebuilding the pool costs ~1 ms per 10k rays: only when what it shows changed.
        if (state.rays !== this.drawnWith.rays || state.selectedPixel !== this.drawnWith.selectedPixel) this.redrawRays();
      }),
    );
    this.tracer.update(this.store.state.scene);
    this.bvhBoxes.update(this.store.state);
  }

  /** The camera's pixels' latest rays, or null before the first trace. */
  get screenRays(): ScreenRays | null {
    return this.tracer.rays;
  }

  /** How many rays and cones are drawn now. */
  get drawn(): RayPoolStats {
    return this.rayPool.stats;
  }

  /** Draws into `view` from now on (the 3D view exists after the lab's first render). */
  attachView(view: LabViewPort): void {
    this.view = view;
    view.setRayLayer(this.rayPool);
    view.setBvhLayer(this.bvhBoxes.object);
    if (this.screenRays) view.setScreenRays(this.screenRays);
  }

  /** Calls `listener` with every new screen of rays; returns the function that stops it. */
  subscribe(listener: (rays: ScreenRays) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  dispose(): void {
    for (const stop of this.cleanup.splice(0)) stop();
    this.tracer.dispose();
    this.tracePool.dispose();
    this.renderPool.dispose();
    this.rayPool.dispose();
    this.bvhBoxes.dispose();
  }

  /** The ray pool follows the rays, the ray options and the picked pixel (it skips work when none changed). */
  private redrawRays(): void {
    const { rays, selectedPixel } = this.store.state;
    this.drawnWith = { rays, selectedPixel };
    this.rayPool.update(this.screenRays, rays, selectedPixel);
    this.view?.requestRender();
  }
}
