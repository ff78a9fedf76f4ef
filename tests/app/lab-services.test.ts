import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { LabServices, type LabViewPort, type LoadProblem } from '../../src/app/lab-services.ts';
import { RenderWorkersUnavailable, type RenderPool } from '../../src/render/render-pool.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { thinTraces } from '../../src/tracer/tree-budget.ts';
import { EDIT_RAY_BUDGET, HEAVY_EDIT_RAYS } from '../../src/view/ray-budget.ts';
import { SETTLE_MS } from '../../src/view/ray-budget-while-editing.ts';
import type { RayBudget } from '../../workers/protocol.ts';

/** A pool that answers every pixel trace at once with a one-ray tree, and remembers what it was asked. */
function fakePool(workers: number | undefined) {
  const scenes: Scene[] = [];
  let disposed = false;
  const pool = {
    workers,
    scenes,
    get disposed() {
      return disposed;
    },
    setScene: (scene: Scene) => void scenes.push(scene),
    // The real tracer on the main thread: the rays are what a worker would send.
    tracePixel: (x: number, y: number, seed = 0): Promise<PixelTrace> => Promise.resolve(tracePixel(buildTracerScene(scenes.at(-1)!, new Map()), x, y, seed)),
    budgets: [] as (RayBudget | undefined)[],
    tracePixels: (first: number, count: number, seed = 0, budget?: RayBudget): Promise<PixelTrace[]> => {
      pool.budgets.push(budget);
      const scene = buildTracerScene(scenes.at(-1)!, new Map());
      const columns = scene.source.camera.pixels[0];
      const traces = Array.from({ length: count }, (_, i) => tracePixel(scene, (first + i) % columns, Math.floor((first + i) / columns), seed));
      // As the worker sends them (workers/render-core.ts).
      return Promise.resolve(budget ? thinTraces(traces, budget.rays, budget.keepPixel === null ? null : budget.keepPixel - first) : traces);
    },
    /** Picture renders: each waits for the test to finish it (`finish`), as a worker would take time. */
    renders: [] as { scene: Scene; finish: () => void }[],
    render(scene: Scene) {
      let finish = () => {};
      const done = new Promise(
        (resolve) => (finish = () => resolve({ cancelled: false, width: 1, height: 1, rgb: new Float32Array([scene.settings.shadows ? 1 : 0, 0, 0]) })),
      );
      pool.renders.push({ scene, finish });
      return { done };
    },
    dispose: () => void (disposed = true),
  };
  return pool;
}

function fakeView(software = false) {
  const calls: string[] = [];
  let rays: ScreenRays | null = null;
  const view: LabViewPort = {
    setScreenRays: (screen) => void ((rays = screen), calls.push('rays')),
    setRayLayer: () => void calls.push('ray-layer'),
    setBvhLayer: () => void calls.push('bvh-layer'),
    requestRender: () => void calls.push('render'),
    software,
    holdCoarse: (budget) => void calls.push(`coarse ${budget}`),
  };
  return { view, calls, rays: () => rays };
}

describe('LabServices: the lab wired apart from any page', () => {
  let pools: ReturnType<typeof fakePool>[];
  let reports: [string, string][];
  let problems: LoadProblem[];
  let services: LabServices;

  beforeEach(() => {
    vi.useFakeTimers();
    pools = [];
    reports = [];
    problems = [];
    services = new LabServices({
      createPool: (workers) => {
        const pool = fakePool(workers);
        pools.push(pool);
        return pool as unknown as RenderPool;
      },
      loadMeshes: () => Promise.resolve(new Map()),
      report: (text, tone) => void reports.push([text, tone]),
      traceFailed: (error) => `could not trace: ${error.message}`,
      cannotLoad: (problem) => void problems.push(problem),
    });
  });

  afterEach(() => {
    services.dispose();
    vi.useRealTimers();
  });

  it('says that the render workers cannot be loaded (with Reload, in the lab), not a message at every edit', async () => {
    await vi.advanceTimersByTimeAsync(1);
    const unavailable = new RenderWorkersUnavailable("the render workers' code could not be loaded (404)");
    pools[1]!.tracePixels = () => Promise.reject(unavailable);
    for (const fov of [50, 55, 60]) {
      services.store.dispatch({ type: 'camera.changed', changes: { fov } });
      await vi.advanceTimersByTimeAsync(1);
    }
    expect(reports).toEqual([]);
    expect(problems).toEqual([...problems].fill({ what: 'tracer', reason: unavailable.message }));
    expect(problems.length).toBeGreaterThan(0);
  });

  it('makes a render pool with a worker per core and a one-worker pool for the screen', () => {
    expect(pools.map((pool) => pool.workers)).toEqual([undefined, 1]);
    expect(services.renderPool).toBe(pools[0]);
  });

  it("traces the store's scene at once on the screen pool; a view attached later (the 3D view loads after the panels) gets its rays, listeners hear the next ones, traced inline", async () => {
    await vi.advanceTimersByTimeAsync(1);
    const { view, calls, rays } = fakeView();
    expect(services.drawn.rays).toBe(0);
    await services.attachView(view);
    expect(calls.slice(0, 3)).toEqual(['ray-layer', 'bvh-layer', 'rays']);
    const [columns, rows] = services.store.state.scene.camera.pixels;
    expect(pools[1]!.scenes).toEqual([services.store.state.scene]);
    expect(services.screenRays?.traces).toHaveLength(columns * rows);
    expect(rays()).toBe(services.screenRays);
    // Every pixel's primary ray at least (the default scene's rays also bounce and go to lights).
    expect(services.drawn.rays).toBeGreaterThanOrEqual(columns * rows);

    const heard: ScreenRays[] = [];
    services.subscribe((screen) => heard.push(screen));
    services.store.dispatch({ type: 'camera.changed', changes: { fov: 50 } });
    // With the view came the inline tracer: the default screen is cheap, so its rays are
    // traced inside the dispatch (in the edit's frame), not by the screen pool's worker.
    expect(heard).toHaveLength(1);
    expect(pools[1]!.scenes).toHaveLength(1);
    await vi.advanceTimersByTimeAsync(1);
    expect(heard).toHaveLength(1);
    expect(rays()).toBe(heard[0]);
    expect(services.screenRays).toBe(heard[0]);
    expect(calls).toContain('render');
  });

  it('traces again after a scene edit, not after a view option, and reports a refused edit', async () => {
    await vi.advanceTimersByTimeAsync(1);
    services.store.dispatch({ type: 'rays.changed', changes: { transparency: 0.5 } });
    await vi.advanceTimersByTimeAsync(1);
    expect(pools[1]!.scenes).toHaveLength(1);
    services.store.dispatch({ type: 'camera.changed', changes: { pixels: [2, 2] } });
    await vi.advanceTimersByTimeAsync(1);
    expect(pools[1]!.scenes).toHaveLength(2);
    expect(services.screenRays?.traces).toHaveLength(4);
    services.store.dispatch({ type: 'settings.changed', changes: { supersampling: 40 } });
    expect(reports).toEqual([['settings.supersampling: must be between 1 and 8, got 40', 'error']]);
  });

  it('a hidden ray kind redraws the rays without tracing again', async () => {
    await services.attachView(fakeView().view);
    await vi.advanceTimersByTimeAsync(1);
    const before = services.drawn.rays;
    services.store.dispatch({ type: 'rays.changed', changes: { showRays: false } });
    expect(before).toBeGreaterThan(0);
    expect(services.drawn.rays).toBe(0);
  });

  it("renders a picture prediction's scenes on a one-worker pool of their own, one at a time, each scene once", async () => {
    const scene = services.store.state.scene;
    const dark = { ...scene, settings: { ...scene.settings, shadows: false } };
    expect(pools).toHaveLength(2); // made when first asked for
    const first = services.renderPicture(scene);
    const second = services.renderPicture(dark);
    expect(services.renderPicture(scene)).toBe(first);
    await vi.advanceTimersByTimeAsync(1);
    const pictures = pools[2]!;
    expect(pictures.workers).toBe(1);
    // A pool's new job cancels its last: the second waits until the first is done.
    expect(pictures.renders.map((render) => render.scene)).toEqual([scene]);
    pictures.renders[0]!.finish();
    expect((await first).rgb[0]).toBe(1);
    await vi.advanceTimersByTimeAsync(1);
    expect(pictures.renders.map((render) => render.scene)).toEqual([scene, dark]);
    pictures.renders[1]!.finish();
    expect((await second).rgb[0]).toBe(0);
  });

  it("on a CPU rasterizer, holds a heavy screen's rays to the budget while the learner edits, coarse, and draws them all once the edits stop", async () => {
    // 4 × 3 pixels of 4 × 4 samples of 4 × 4 lens points: traced in the worker, thousands of rays.
    const { store } = services;
    store.dispatch({ type: 'camera.changed', changes: { pixels: [4, 3], aperture: 0.2, lensSamples: 4 } });
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 4 } });
    const { view, calls } = fakeView(true);
    await services.attachView(view);
    await vi.advanceTimersByTimeAsync(1);
    const all = services.drawn.rays;
    expect(all).toBeGreaterThan(4 * EDIT_RAY_BUDGET);
    const screenPool = pools[1]!;
    const asked = screenPool.budgets.length;

    store.dispatch({ type: 'material.changed', id: 'red-ball', changes: { shininess: 80 } }, { live: true });
    await vi.advanceTimersByTimeAsync(1);
    // More rays than the edit budget: held to the heavy screen's fewer, each pixel traced from one of its samples.
    expect(screenPool.budgets.slice(asked)).toEqual([{ rays: HEAVY_EDIT_RAYS, keepPixel: null, oneSample: true }]);
    expect(services.drawn.rays).toBeLessThanOrEqual(HEAVY_EDIT_RAYS + 50);
    expect(services.drawn.rays).toBeGreaterThan(HEAVY_EDIT_RAYS / 2);
    expect(calls).toContain(`coarse ${HEAVY_EDIT_RAYS}`);
    // The learner lets go (on the value the drag reached: nothing changes); a moment later every ray, traced again, sharp.
    store.dispatch({ type: 'material.changed', id: 'red-ball', changes: { shininess: 80 } });
    await vi.advanceTimersByTimeAsync(SETTLE_MS);
    await vi.advanceTimersByTimeAsync(1);
    expect(screenPool.budgets.at(-1)).toBeUndefined();
    expect(services.drawn.rays).toBe(all);
    expect(calls.at(-1)).toBe('coarse null');
  });

  it('disposes both pools', () => {
    services.dispose();
    expect(pools.every((pool) => pool.disposed)).toBe(true);
  });
});
