import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { createNodeRenderPool } from '../../src/cli/node-worker-port.ts';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { PIXELS_PER_REQUEST, ScreenTracer, type ScreenTracePool } from '../../src/render/screen-tracer.ts';
import { estimateRender } from '../../src/render/render-estimate.ts';
import { SLICE_RAYS, settledSlices } from '../../src/render/settled-slices.ts';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { LabPaths } from '../../src/tracer/lab-paths.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import { tracePixels } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import type { RayBudget } from '../../workers/protocol.ts';

const noMeshes = () => Promise.resolve<MeshLibrary>(new Map());
const BUDGET: RayBudget = { rays: 1200, keepPixel: null };

/** The default scene's 8 × 6 screen with 4 × 4 samples at 4 shutter times: dear enough to be sliced. */
function dearScene(lightIntensity = 1): Scene {
  const scene = defaultScene();
  return {
    ...scene,
    lights: scene.lights.map((light) => ({ ...light, intensity: lightIntensity })),
    settings: { ...scene.settings, supersampling: 4, timeSamples: 4 },
  };
}

/** The next screen the tracer publishes (not the one it has now). */
function nextRays(tracer: ScreenTracer): Promise<ScreenRays> {
  const now = tracer.rays;
  return new Promise((resolve) => {
    const unsubscribe = tracer.subscribe((rays) => {
      if (rays === now) return;
      unsubscribe();
      resolve(rays);
    });
  });
}

/** A screen of `columns` × `rows` pixels whose budget sent none of their rays, with how many each traced. */
function countedScreen(scene: Scene, raysOf: (pixel: number) => number): ScreenRays {
  const [columns, rows] = scene.camera.pixels;
  const traces = Array.from({ length: columns * rows }, (_, p): PixelTrace => ({
    pixel: [p % columns, Math.floor(p / columns)],
    color: [0, 0, 0],
    rays: [],
    traced: raysOf(p),
  }));
  return { columns, rows, traces, scene };
}

describe('the settled screen in slices', () => {
  it('fills each slice with pixels up to SLICE_RAYS of the rays they traced before, at least one, at most `most`', () => {
    const scene = dearScene(); // 8 × 6
    expect(
      settledSlices(
        scene,
        countedScreen(scene, () => 2267),
        64,
      ),
    ).toEqual(Array(48).fill(1));
    expect(
      settledSlices(
        scene,
        countedScreen(scene, () => SLICE_RAYS / 4),
        64,
      ),
    ).toEqual(Array(12).fill(4));
    expect(
      settledSlices(
        scene,
        countedScreen(scene, () => 10),
        64,
      ),
    ).toEqual([48]);
    expect(
      settledSlices(
        scene,
        countedScreen(scene, () => 10),
        20,
      ),
    ).toEqual([20, 20, 8]);
    // A dear pixel among light ones takes a slice of its own.
    expect(
      settledSlices(
        scene,
        countedScreen(scene, (p) => (p === 5 ? 2 * SLICE_RAYS : 50)),
        64,
      ),
    ).toEqual([5, 1, 42]);
    // Another screen size: the estimate per pixel.
    const bigger = { ...scene, camera: { ...scene.camera, pixels: [16, 16] as [number, number] } };
    const guess = estimateRender(scene, 1, 1).raysPerPixel;
    const [firstSlice] = settledSlices(
      scene,
      countedScreen(bigger, () => 1),
      64,
    );
    expect(firstSlice).toBe(Math.min(48, Math.floor(SLICE_RAYS / guess)));
  });

  it('sizes the slices by the estimate after a screen traced from one sample per pixel, whose rays nobody counted', () => {
    const scene = dearScene();
    const guess = estimateRender(scene, 1, 1).raysPerPixel;
    const sampled = countedScreen(scene, () => 2267);
    for (const trace of sampled.traces) {
      delete trace.traced;
      trace.onlySample = 5;
    }
    expect(settledSlices(scene, sampled, 64)[0]).toBe(Math.min(48, Math.max(1, Math.floor(SLICE_RAYS / guess))));
    expect(
      settledSlices(
        scene,
        countedScreen(scene, () => 2267),
        64,
      )[0],
    ).toBe(1);
  });

  it('publishes, sliced in a worker, exactly the trees of the screen traced in one go', async () => {
    const scene = dearScene();
    const pool = createNodeRenderPool(1);
    const requests: number[] = [];
    const counting: ScreenTracePool = {
      setScene: (...args) => pool.setScene(...args),
      tracePixel: (...args) => pool.tracePixel(...args),
      tracePaths: (...args) => pool.tracePaths(...args),
      tracePixels: (first, count, seed, budget) => (budget ? undefined : requests.push(count), pool.tracePixels(first, count, seed, budget)),
    };
    const tracer = new ScreenTracer(counting, noMeshes);
    try {
      tracer.setBudget(BUDGET);
      const thinned = nextRays(tracer);
      tracer.update(scene);
      expect((await thinned).traces.some((trace) => trace.traced !== undefined)).toBe(true);
      const settled = nextRays(tracer);
      tracer.setBudget(null);
      const rays = await settled;
      const [columns, rows] = scene.camera.pixels;
      expect(requests).toEqual(settledSlices(scene, await thinned, PIXELS_PER_REQUEST));
      expect(requests.length).toBeGreaterThan(1);
      expect(rays.scene).toBe(scene);
      expect(rays.traces).toStrictEqual(tracePixels(buildTracerScene(scene, new Map()), 0, columns * rows, DEFAULT_SEED));
      expect(rays.traces.some((trace) => trace.traced !== undefined)).toBe(false);
    } finally {
      tracer.dispose();
      pool.dispose();
    }
  }, 60_000);
});

/** A pool whose blocks answer only when the test says so. */
class FakePool implements ScreenTracePool {
  readonly requests: { scene: Scene; first: number; count: number; budget?: RayBudget; answer(): void }[] = [];
  private scene: Scene | null = null;

  setScene(scene: Scene): void {
    this.scene = scene;
  }

  tracePixel(): Promise<PixelTrace> {
    return Promise.reject(new Error('not here'));
  }

  tracePaths(): Promise<LabPaths> {
    return Promise.reject(new Error('not here'));
  }

  tracePixels(first: number, count: number, _seed?: number, budget?: RayBudget): Promise<PixelTrace[]> {
    const scene = this.scene!;
    const columns = scene.camera.pixels[0];
    return new Promise((resolve) => {
      // As a budget sends them: no rays, and how many each pixel traced (the largest settings' 2,267).
      const traces = Array.from({ length: count }, (_, i): PixelTrace => ({
        pixel: [(first + i) % columns, Math.floor((first + i) / columns)],
        color: [0, 0, 0],
        rays: [],
        traced: 2267,
      }));
      this.requests.push({ scene, first, count, budget, answer: () => resolve(traces) });
    });
  }
}

describe('a new edit during the settled screen', () => {
  let pool: FakePool;
  let tracer: ScreenTracer;
  let published: ScreenRays[];

  beforeEach(() => {
    vi.useFakeTimers();
    pool = new FakePool();
    tracer = new ScreenTracer(pool, noMeshes);
    published = [];
    tracer.subscribe((rays) => published.push(rays));
  });

  afterEach(() => {
    tracer.dispose();
    vi.useRealTimers();
  });

  it('stops its remaining slices at once; the edit’s own trace starts after the one slice under way', async () => {
    const first = dearScene(1);
    const edited = dearScene(0.5);
    const slice = 1; // 2 × 2,267 rays would be more than SLICE_RAYS
    tracer.setBudget(BUDGET);
    tracer.update(first);
    await vi.advanceTimersByTimeAsync(0);
    pool.requests[0].answer();
    await vi.advanceTimersByTimeAsync(0);
    expect(published).toHaveLength(1);
    // The edits stop: the full screen, one slice in flight at a time.
    tracer.setBudget(null);
    await vi.advanceTimersByTimeAsync(0);
    pool.requests[1].answer();
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.requests.slice(1).map(({ first: at, count, budget }) => [at, count, budget])).toEqual([
      [0, slice, undefined],
      [slice, slice, undefined],
    ]);
    // A new edit, as the lab makes it: the budget again, then the scene.
    tracer.setBudget(BUDGET);
    tracer.update(edited);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.requests).toHaveLength(3);
    pool.requests[2].answer();
    await vi.advanceTimersByTimeAsync(0);
    // No further slice of the settled screen: the edit's scene, within its budget, is next.
    expect(pool.requests).toHaveLength(4);
    expect(pool.requests[3].scene).toBe(edited);
    expect(pool.requests[3].budget).toEqual({ rays: BUDGET.rays, keepPixel: null });
    pool.requests[3].answer();
    await vi.advanceTimersByTimeAsync(0);
    // The settled screen was never published, half done; the edit's was.
    expect(published.map((rays) => rays.scene)).toEqual([first, edited]);
    expect(published.every((rays) => rays.traces.every((trace) => trace !== undefined))).toBe(true);
  });

  it('does not give way while no budget was ever set: a running trace is published whole, as before', async () => {
    const first = dearScene(1);
    const edited = dearScene(0.5);
    tracer.update(first);
    await vi.advanceTimersByTimeAsync(0);
    tracer.update(edited);
    expect(pool.requests.map(({ count }) => count)).toEqual([48]);
    pool.requests[0].answer();
    await vi.advanceTimersByTimeAsync(0);
    expect(published.map((rays) => rays.scene)).toEqual([first]);
    expect(pool.requests[1].scene).toBe(edited);
  });
});
