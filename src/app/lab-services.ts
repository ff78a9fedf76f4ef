import { issueText } from '../i18n/issue-text.ts';
import { initialState, type LabState } from '../lab-state/lab-state.ts';
import { Store } from '../lab-state/store.ts';
import type { RenderImage } from '../render/render-job.ts';
import { RenderWorkersUnavailable, type RenderPool } from '../render/render-pool.ts';
import { LazyModule } from '../util/lazy-module.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import type { Scene } from '../scene/scene.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import type { LabPaths } from '../tracer/lab-paths.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import type { RayFocus } from '../view/ray-focus.ts';
import { ScreenTracer } from '../render/screen-tracer.ts';
import { PathPixelFocus } from './path-pixel-focus.ts';
import { defaultScene } from '../scene/scene-defaults.ts';
import type { BvhBoxes } from '../view/bvh-boxes.ts';
import type { LabView } from '../view/lab-view.ts';
import type { RayPool, RayPoolStats } from '../view/ray-pool.ts';
import type { RayBudgetWhileEditing } from '../view/ray-budget-while-editing.ts';
import type { MeshLoader } from '../view/scene-sync.ts';

/** What the services draw into: the lab's three.js view. */
export type LabViewPort = Pick<LabView, 'setScreenRays' | 'setRayLayer' | 'setBvhLayer' | 'requestRender' | 'software' | 'holdCoarse'>;

export interface LabServicesOptions {
  /** A render worker pool with `workers` workers (default: one per core). */
  createPool(workers?: number): RenderPool;
  loadMeshes: MeshLoader;
  /** A message for the learner: a refused change, rays that could not be traced. */
  report(text: string, tone: 'info' | 'error'): void;
  /** The words of a tracing failure (the UI translates them). */
  traceFailed(error: Error): string;
  /** Code that could not be loaded: the render workers', or the 3D view's ray layers' (the UI says so, with Reload). */
  cannotLoad(problem: LoadProblem): void;
}

/** What could not be loaded, and the browser's reason. */
export interface LoadProblem {
  what: 'tracer' | 'view-layers';
  reason: string;
}

/**
 * The three.js layers' code, loaded when the first 3D view attaches; tried a few times, then
 * failed for good (a tab of a build that a newer one replaced, offline): lazy-module.ts.
 */
const viewLayersCode = new LazyModule(() =>
  Promise.all([
    import('../view/ray-pool.ts'),
    import('../view/bvh-boxes.ts'),
    import('../render/inline-screen-tracer.ts'),
    import('../view/ray-budget-while-editing.ts'),
  ]),
);

/**
 * The lab's services and how they are wired, apart from any page: the one store, the render
 * pool for full images, a one-worker pool and the screen tracer that traces the camera's
 * pixels, the ray pool that draws their rays and the BVH boxes.
 *
 * - A new scene is traced again (a cheap screen at once, on the main thread once the 3D view
 *   has loaded; else in the worker, at once or after the running trace, latest wins) and its
 *   boxes redrawn.
 * - New rays, ray options or a picked pixel redraw the rays; the view draws on demand.
 * - On a CPU rasterizer, while the learner edits the scene or the ray options, a screen
 *   traced in the worker sends, and the view draws, a budget of its rays; all of them once
 *   the edits stop (view/ray-budget.ts).
 * - Listeners hear when the screen's rays change (the flat preview shows them).
 *
 * The ray pool and the boxes are three.js objects: they are made when the 3D view attaches,
 * from modules loaded then, so that three.js is not in a student's first load (the panels
 * and the tasks show while it arrives).
 */
export class LabServices {
  /** The app's one source of truth. */
  readonly store = new Store(initialState(defaultScene()));
  readonly renderPool: RenderPool;
  /** The rays' instanced meshes and the acceleration levels' boxes, once a view is attached. */
  private layers: { rays: RayPool; boxes: BvhBoxes } | null = null;
  /** The ray debugger's focus, kept for a ray pool made after it was set. */
  private focus: RayFocus | null = null;
  /** A chosen pixel's paths in path mode, drawn while the debugger draws nothing (path-pixel-focus.ts). */
  private pixelPaths: RayFocus | null = null;
  private readonly pathPixel = new PathPixelFocus(
    (x, y, keep) => this.tracer.tracePaths(x, y, keep),
    (focus) => {
      this.pixelPaths = focus;
      this.setRayFocus(this.focus);
    },
  );
  /** When the rays are held to a budget: on a CPU rasterizer, once its view is attached. */
  private budget: RayBudgetWhileEditing | null = null;
  /** The scene and ray options last seen, to tell an edit. */
  private seen: Pick<LabState, 'scene' | 'rays' | 'selectedPixel'>;
  private readonly loadMeshes: MeshLoader;
  private disposed = false;
  private readonly tracePool: RenderPool;
  private readonly tracer: ScreenTracer;
  private view: LabViewPort | null = null;
  /** The ray options and picked pixel the pool last drew with. */
  private drawnWith: Pick<LabState, 'rays' | 'selectedPixel'>;
  private readonly listeners = new Set<(rays: ScreenRays) => void>();
  private readonly cleanup: (() => void)[] = [];
  private readonly createPool: LabServicesOptions['createPool'];
  private readonly cannotLoad: LabServicesOptions['cannotLoad'];
  /** One worker for picture predictions, made when the first is asked for: the render window's pool stays the learner's. */
  private picturePool: RenderPool | null = null;
  /** Each picture scene's render, by its JSON: a quiz shown again (or in the other language) does not render again. */
  private readonly pictures = new Map<string, Promise<RenderImage>>();
  /** The picture renders waiting for the one before: a pool runs one job at a time and a new one cancels the last. */
  private pictureQueue: Promise<unknown> = Promise.resolve();

  constructor(options: LabServicesOptions) {
    this.createPool = options.createPool;
    this.renderPool = options.createPool();
    this.tracePool = options.createPool(1);
    this.drawnWith = { rays: this.store.state.rays, selectedPixel: this.store.state.selectedPixel };
    this.seen = this.store.state;
    this.loadMeshes = options.loadMeshes;
    this.tracer = new ScreenTracer(this.tracePool, options.loadMeshes);
    // Workers whose code cannot be loaded are said once, with Reload, not at every edit.
    this.tracer.onError = (error) =>
      error instanceof RenderWorkersUnavailable
        ? options.cannotLoad({ what: 'tracer', reason: error.message })
        : options.report(options.traceFailed(error), 'error');
    this.cannotLoad = options.cannotLoad;
    this.cleanup.push(
      this.tracer.subscribe((rays) => {
        this.view?.setScreenRays(rays);
        this.pathPixel.follow(this.store.state, rays);
        this.redrawRays();
        this.prepareBudget();
        for (const listener of [...this.listeners]) listener(rays);
      }),
      this.store.subscribe((state, _action, error, live) => {
        if (error) options.report(error.map(issueText).join('\n'), 'error');
        this.followBudget(state, live === true);
        this.tracer.update(state.scene);
        this.pathPixel.follow(state, this.screenRays);
        this.layers?.boxes.update(state);
        // Rebuilding the pool costs ~1 ms per 10k rays: only when what it shows changed.
        if (state.rays !== this.drawnWith.rays || state.selectedPixel !== this.drawnWith.selectedPixel) this.redrawRays();
      }),
    );
    this.tracer.update(this.store.state.scene);
  }

  /** The camera's pixels' latest rays, or null before the first trace. */
  get screenRays(): ScreenRays | null {
    return this.tracer.rays;
  }

  /** How many rays and cones are drawn now (none before a view is attached). */
  get drawn(): RayPoolStats {
    return this.layers?.rays.stats ?? { rays: 0, cones: 0, arrows: 0, drawCalls: 0, instanceBytes: 0 };
  }

  /**
   * Draws into `view` from now on (the 3D view loads after the lab's first render): loads and
   * makes the three.js layers the first time (and lets the screen tracer trace cheap screens
   * inline: its code comes with them), and draws what is there already.
   */
  async attachView(view: LabViewPort): Promise<void> {
    let modules;
    try {
      modules = await viewLayersCode.load();
    } catch {
      if (!this.disposed) this.cannotLoad({ what: 'view-layers', reason: viewLayersCode.problem });
      return;
    }
    const [{ RayPool }, { BvhBoxes }, { InlineScreenTracer }, { RayBudgetWhileEditing }] = modules;
    if (this.disposed) return;
    if (!this.layers) {
      this.layers = { rays: new RayPool(), boxes: new BvhBoxes(() => this.view?.requestRender(), this.loadMeshes) };
      this.layers.rays.setFocus(this.focus ?? this.pixelPaths);
      this.tracer.traceInline(new InlineScreenTracer());
    }
    if (view.software && !this.budget)
      this.budget = new RayBudgetWhileEditing(
        () => this.applyBudget(),
        undefined,
        () => this.screenRays,
      );
    this.view = view;
    view.setRayLayer(this.layers.rays);
    view.setBvhLayer(this.layers.boxes.object);
    if (this.screenRays) view.setScreenRays(this.screenRays);
    this.layers.boxes.update(this.store.state);
    this.redrawRays();
  }

  /** Pixel (x, y)'s tree with each hit's shading terms, for the ray debugger (the scene of the latest screen). */
  traceWithTerms(x: number, y: number): Promise<PixelTrace> {
    return this.tracer.traceWithTerms(x, y);
  }

  /** Pixel (x, y)'s first `keep` sample paths in path mode, for the path debugger (the scene of the latest screen); bound, so lit sees one function. */
  readonly tracePaths = (x: number, y: number, keep: number): Promise<LabPaths> => this.tracer.tracePaths(x, y, keep);

  /** The ray debugger's pixel drawn instead of the screen's rays (null: the screen again). */
  setRayFocus(focus: RayFocus | null): void {
    this.focus = focus;
    this.layers?.rays.setFocus(focus ?? this.pixelPaths);
    this.redrawRays();
  }

  /**
   * A small render of `scene` at its image size, for a picture prediction: one at a time on
   * a worker of its own, each scene rendered once (renders are seeded, so the same scene
   * always gives the same picture).
   */
  renderPicture(scene: Scene): Promise<RenderImage> {
    const key = JSON.stringify(scene);
    let picture = this.pictures.get(key);
    if (!picture) {
      picture = this.pictureQueue.then(async () => {
        this.picturePool ??= this.createPool(1);
        const meshes = await this.loadMeshes(meshNamesInScene(scene));
        const result = await this.picturePool.render(scene, meshes, { preview: false }).done;
        if (result.cancelled) throw new Error('the picture was cancelled');
        return result;
      });
      // A failed picture is tried again when asked again; the queue goes on either way.
      picture.catch(() => this.pictures.delete(key));
      this.pictureQueue = picture.catch(() => undefined);
      this.pictures.set(key, picture);
    }
    return picture;
  }

  /** Calls `listener` with every new screen of rays; returns the function that stops it. */
  subscribe(listener: (rays: ScreenRays) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  dispose(): void {
    this.disposed = true;
    for (const stop of this.cleanup.splice(0)) stop();
    this.tracer.dispose();
    this.tracePool.dispose();
    this.renderPool.dispose();
    this.picturePool?.dispose();
    this.budget?.dispose();
    this.layers?.rays.dispose();
    this.layers?.boxes.dispose();
    this.layers = null;
  }

  /**
   * An edit of the scene or the ray options holds the rays to the budget until the edits
   * stop (`live`: a value still being dragged); before the edit's screen is traced, so that
   * it is traced within the budget. A pixel chosen meanwhile keeps all its rays.
   */
  private followBudget(state: LabState, live: boolean): void {
    const seen = this.seen;
    this.seen = state;
    if (state.scene !== seen.scene || state.rays !== seen.rays) this.budget?.edited(live);
    else if (!live) this.budget?.letGo();
    if (state.selectedPixel !== seen.selectedPixel && this.budget?.budget != null) this.applyBudget();
  }

  /** The screen tracer and the ray pool follow the budget in force; the view draws again. */
  private applyBudget(): void {
    const rays = this.budget?.budget ?? null;
    const pixel = this.store.state.selectedPixel;
    const columns = this.store.state.scene.camera.pixels[0];
    const oneSample = this.budget?.oneSample === true;
    this.tracer.setBudget(rays === null ? null : { rays, keepPixel: pixel ? pixel[1] * columns + pixel[0] : null, oneSample });
    this.layers?.rays.setBudget(rays);
    this.afterRaysChanged();
  }

  /**
   * The view draws again, coarse while some rays are left out; the sharp frame after has them
   * all (asked for first: going sharp draws at once, in place of the frame asked for).
   */
  private afterRaysChanged(): void {
    this.view?.requestRender();
    this.view?.holdCoarse(this.layers?.rays.thinning ? (this.budget?.budget ?? null) : null);
  }

  /**
   * While every ray is drawn, the rays the next edit's budget keeps are chosen when the page
   * is idle, not in that edit's step (a heavy screen's choice took 0.45 s there).
   */
  private prepareBudget(): void {
    const budget = this.budget;
    if (!budget || budget.budget !== null) return;
    whenIdle(() => {
      if (!this.disposed && budget.budget === null) this.layers?.rays.prepareBudget(budget.editBudget);
    });
  }

  /** The ray pool follows the rays, the ray options and the picked pixel (it skips work when none changed). */
  private redrawRays(): void {
    const { rays, selectedPixel } = this.store.state;
    this.drawnWith = { rays, selectedPixel };
    this.layers?.rays.update(this.screenRays, rays, selectedPixel);
    this.afterRaysChanged();
  }
}

/** Runs `task` when the page is idle (soon, where there is no idle callback). */
function whenIdle(task: () => void): void {
  if (typeof requestIdleCallback === 'function') requestIdleCallback(task, { timeout: 2000 });
  else setTimeout(task, 0);
}
