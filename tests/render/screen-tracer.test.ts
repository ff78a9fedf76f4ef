import { afterEach, beforeAll, beforeEach, describe, expect, it, vi } from 'vitest';
import { pathToFileURL } from 'node:url';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { RenderPool } from '../../src/render/render-pool.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { InlineScreenTracer } from '../../src/render/inline-screen-tracer.ts';
import { PIXELS_PER_REQUEST, REQUESTS_IN_FLIGHT, ScreenTracer, TRACE_RETRIES, type ScreenTracePool } from '../../src/render/screen-tracer.ts';
import { createNodeRenderPool, createNodeWorkerPort } from '../../src/cli/node-worker-port.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { LabPaths } from '../../src/tracer/lab-paths.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import type { RayBudget } from '../../workers/protocol.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

const NO_MESHES: MeshLibrary = new Map();
const noMeshes = () => Promise.resolve(NO_MESHES);

function sceneWithPixels(columns: number, rows: number): Scene {
  const scene = defaultScene();
  return { ...scene, camera: { ...scene.camera, pixels: [columns, rows] } };
}

/** A request for pixels first … first + count - 1 of the screen. */
interface Request {
  scene: Scene;
  first: number;
  count: number;
  seed: number | undefined;
  budget: RayBudget | undefined;
  resolve(traces: PixelTrace[]): void;
  reject(error: Error): void;
}

/** A pool whose traces answer only when the test says so. */
class FakePool implements ScreenTracePool {
  readonly scenes: Scene[] = [];
  readonly requests: Request[] = [];
  readonly pending = new Set<Request>();

  setScene(scene: Scene): void {
    this.scenes.push(scene);
  }

  tracePixel(): Promise<PixelTrace> {
    return Promise.reject(new Error('the screen tracer traces pixels in blocks'));
  }

  tracePaths(): Promise<LabPaths> {
    return Promise.reject(new Error('these tests trace no paths'));
  }

  tracePixels(first: number, count: number, seed?: number, budget?: RayBudget): Promise<PixelTrace[]> {
    const scene = this.scenes[this.scenes.length - 1];
    return new Promise((resolve, reject) => {
      const request: Request = { scene, first, count, seed, budget, resolve, reject };
      request.resolve = (traces) => (this.pending.delete(request), resolve(traces));
      request.reject = (error) => (this.pending.delete(request), reject(error));
      this.requests.push(request);
      this.pending.add(request);
    });
  }

  /** Answers every pending request (and those they lead to), letting the tracer's awaits run. */
  async answerAll(): Promise<void> {
    while (this.pending.size > 0) {
      for (const request of [...this.pending]) {
        const columns = request.scene.camera.pixels[0];
        request.resolve(
          Array.from({ length: request.count }, (_, i) => {
            const [x, y] = [(request.first + i) % columns, Math.floor((request.first + i) / columns)];
            return { pixel: [x, y], color: [x, y, 0], rays: [] };
          }),
        );
      }
      await vi.advanceTimersByTimeAsync(0);
    }
  }
}

describe('ScreenTracer (fake pool)', () => {
  let pool: FakePool;
  let tracer: ScreenTracer;
  let published: ScreenRays[];
  let errors: Error[];

  beforeEach(() => {
    vi.useFakeTimers();
    pool = new FakePool();
    tracer = new ScreenTracer(pool, noMeshes);
    published = [];
    errors = [];
    tracer.onError = (error) => errors.push(error);
    tracer.subscribe((rays) => published.push(rays));
  });

  afterEach(() => {
    tracer.dispose();
    vi.useRealTimers();
  });

  it('traces every pixel of the camera screen with the render seed and publishes them in order', async () => {
    tracer.update(sceneWithPixels(3, 2));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(published).toHaveLength(1);
    const [rays] = published;
    expect([rays.columns, rays.rows]).toEqual([3, 2]);
    expect(rays.traces.map((trace) => trace.pixel)).toEqual([
      [0, 0],
      [1, 0],
      [2, 0],
      [0, 1],
      [1, 1],
      [2, 1],
    ]);
    expect(pool.requests.every((request) => request.seed === DEFAULT_SEED)).toBe(true);
    expect(tracer.rays).toBe(rays);
    expect(errors).toEqual([]);
  });

  it('traces a scene at once when idle, else after the running trace, with only the newest scene that came meanwhile', async () => {
    const scenes = [sceneWithPixels(1, 1), sceneWithPixels(2, 1), sceneWithPixels(2, 2), sceneWithPixels(3, 1)];
    tracer.update(scenes[0]);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([scenes[0]]);
    tracer.update(scenes[1]);
    tracer.update(scenes[2]);
    tracer.update(scenes[3]);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([scenes[0]]); // the running trace is never dropped
    await pool.answerAll();
    // The running trace published, then the newest scene was traced; the ones in between never.
    expect(pool.scenes).toEqual([scenes[0], scenes[3]]);
    expect(published.map((rays) => rays.traces.length)).toEqual([1, 3]);
    expect(tracer.rays?.columns).toBe(3);
  });

  it('asks each block for its share of a budget, and traces the screen again in full once the budget ends', async () => {
    const scene = sceneWithPixels(16, 8); // two blocks
    tracer.setBudget({ rays: 1000, keepPixel: 70 });
    tracer.update(scene);
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(pool.requests.map(({ first, budget }) => [first, budget])).toEqual([
      [0, { rays: 500, keepPixel: 70 }],
      [64, { rays: 500, keepPixel: 70 }],
    ]);
    // The budget ends: the same scene again, every ray.
    tracer.setBudget(null);
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(pool.requests.slice(2).map(({ scene: traced, budget }) => [traced, budget])).toEqual([
      [scene, undefined],
      [scene, undefined],
    ]);
    expect(published).toHaveLength(2);
    // A budget that starts traces nothing again: the screen shown has every ray.
    tracer.setBudget({ rays: 1000, keepPixel: null });
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.requests).toHaveLength(4);
  });

  it('ignores the same scene object again (only scene changes trace)', async () => {
    const scene = sceneWithPixels(1, 1);
    tracer.update(scene);
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    tracer.update(scene);
    await vi.advanceTimersByTimeAsync(1000);
    expect(pool.scenes).toHaveLength(1);
    expect(published).toHaveLength(1);
  });

  it('asks for PIXELS_PER_REQUEST pixels a request, at most REQUESTS_IN_FLIGHT requests at a time', async () => {
    // More blocks than may be in flight, the last one short.
    const rows = Math.ceil(((REQUESTS_IN_FLIGHT + 1) * PIXELS_PER_REQUEST) / 16) + 1;
    const pixels = 16 * rows;
    tracer.update(sceneWithPixels(16, rows));
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.pending.size).toBe(REQUESTS_IN_FLIGHT);
    await pool.answerAll();
    const blocks = Array.from({ length: Math.ceil(pixels / PIXELS_PER_REQUEST) }, (_, i) => [
      i * PIXELS_PER_REQUEST,
      Math.min(PIXELS_PER_REQUEST, pixels - i * PIXELS_PER_REQUEST),
    ]);
    expect(blocks.length).toBeGreaterThan(REQUESTS_IN_FLIGHT);
    expect(pool.requests.map(({ first, count }) => [first, count])).toEqual(blocks);
    expect(published[0].traces.map((trace) => trace.pixel)).toEqual(Array.from({ length: pixels }, (_, i) => [i % 16, Math.floor(i / 16)]));
  });

  it('a newer scene waits for the running trace, which is published whole before the newer one is traced', async () => {
    const older = sceneWithPixels(16, 16);
    const newer = sceneWithPixels(2, 1);
    tracer.update(older);
    await vi.advanceTimersByTimeAsync(0);
    tracer.update(newer);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([older]);
    await pool.answerAll();
    expect(pool.scenes).toEqual([older, newer]);
    expect(pool.requests.filter((request) => request.scene === older)).toHaveLength(256 / PIXELS_PER_REQUEST);
    expect(published.map((rays) => [rays.columns, rays.rows])).toEqual([
      [16, 16],
      [2, 1],
    ]);
  });

  it('reports a trace that fails past its retries to onError once, and publishes nothing for that scene', async () => {
    // Twice as many blocks as may be in flight: none is asked for after the failure.
    tracer.update(sceneWithPixels(16, (2 * REQUESTS_IN_FLIGHT * PIXELS_PER_REQUEST) / 16));
    await vi.advanceTimersByTimeAsync(0);
    // Each failure is asked again until the screen's TRACE_RETRIES are spent.
    for (let failure = 0; failure <= TRACE_RETRIES; failure++) {
      const [block] = [...pool.pending];
      block.reject(new Error(`worker died ${failure}`));
      await vi.advanceTimersByTimeAsync(0);
    }
    const [other] = [...pool.pending];
    other.reject(new Error('worker died again'));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(errors.map((error) => error.message)).toEqual([`worker died ${TRACE_RETRIES}`]);
    expect(pool.requests).toHaveLength(REQUESTS_IN_FLIGHT + TRACE_RETRIES);
    expect(published).toEqual([]);
  });

  it('reports a model that cannot load, and not the errors of a scene already replaced', async () => {
    let fail = true;
    const loading = new ScreenTracer(pool, async () => {
      if (fail) throw new Error('mesh "teapot" is not one of the shipped models');
      return NO_MESHES;
    });
    const seen: string[] = [];
    loading.onError = (error) => seen.push(error.message);
    loading.update(sceneWithPixels(1, 1));
    await vi.advanceTimersByTimeAsync(0);
    expect(seen).toEqual(['mesh "teapot" is not one of the shipped models']);

    fail = false;
    loading.update(sceneWithPixels(2, 1));
    await vi.advanceTimersByTimeAsync(0);
    const [stale] = [...pool.pending];
    loading.update(sceneWithPixels(1, 2));
    stale.reject(new Error('stale failure'));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(seen).toHaveLength(1);
    expect(loading.rays?.rows).toBe(2);
    loading.dispose();
  });

  it('gives a new subscriber the last screen at once; unsubscribe and dispose stop the calls', async () => {
    tracer.update(sceneWithPixels(1, 1));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    const late: ScreenRays[] = [];
    const unsubscribe = tracer.subscribe((rays) => late.push(rays));
    expect(late).toEqual([published[0]]);
    unsubscribe();
    tracer.update(sceneWithPixels(2, 1));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(late).toHaveLength(1);
    expect(published).toHaveLength(2);

    tracer.dispose();
    tracer.update(sceneWithPixels(3, 1));
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toHaveLength(2);
  });

  it('reports a throwing subscriber and still calls the others', async () => {
    tracer.subscribe(() => {
      throw new Error('listener bug');
    });
    const after: ScreenRays[] = [];
    tracer.subscribe((rays) => after.push(rays));
    tracer.update(sceneWithPixels(1, 1));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(errors.map((error) => error.message)).toEqual(['listener bug']);
    expect(after).toHaveLength(1);
  });
});

describe('ScreenTracer with an inline tracer (fake pool)', () => {
  let pool: FakePool;
  let tracer: ScreenTracer;
  let inline: InlineScreenTracer;
  let idle: (() => void)[];
  let published: ScreenRays[];
  let errors: Error[];
  let prism: MeshLibrary;
  /** The default scene's 16 × 16 screen: cheap enough to trace inline. */
  const cheap = (intensity = 1): Scene => {
    const scene = sceneWithPixels(16, 16);
    return { ...scene, lights: scene.lights.map((light) => ({ ...light, intensity })) };
  };
  /** The same with 4 × 4 supersampling: too dear, so the worker's. */
  const dear = (): Scene => {
    const scene = cheap();
    return { ...scene, settings: { ...scene.settings, supersampling: 4 } };
  };

  beforeAll(async () => {
    prism = await loadMeshesFromDisk(['prism']);
  });

  beforeEach(() => {
    vi.useFakeTimers();
    pool = new FakePool();
    idle = [];
    inline = new InlineScreenTracer((callback) => void idle.push(callback));
    // Resolved at once, as a fake timer's advance cannot wait for the disk.
    tracer = new ScreenTracer(pool, (names) => Promise.resolve(new Map(names.map((name) => [name, prism.get(name)!]))));
    published = [];
    errors = [];
    tracer.onError = (error) => errors.push(error);
    tracer.subscribe((rays) => published.push(rays));
    tracer.traceInline(inline);
  });

  afterEach(() => {
    tracer.dispose();
    vi.useRealTimers();
  });

  it('traces a cheap screen inside update, with the trees the core gives, and the debugger’s pixel too', async () => {
    const scene = cheap(0.8);
    tracer.update(scene);
    // Published before update returned: no worker, no await.
    expect(published).toHaveLength(1);
    expect(pool.scenes).toEqual([]);
    const core = buildTracerScene(scene, NO_MESHES);
    expect(published[0].scene).toBe(scene);
    expect(published[0].traces[37]).toEqual(tracePixel(core, 5, 2, DEFAULT_SEED));
    // The fake pool refuses single pixels: the debugger's trace is the inline one.
    expect(await tracer.traceWithTerms(5, 2)).toEqual(tracePixel(core, 5, 2, DEFAULT_SEED, { terms: true }));
  });

  it('sends a dear screen to the worker, and the debugger’s pixel with it', async () => {
    tracer.update(dear());
    expect(published).toEqual([]);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toHaveLength(1);
    await pool.answerAll();
    expect(published).toHaveLength(1);
    await expect(tracer.traceWithTerms(0, 0)).rejects.toThrow(/in blocks/);
  });

  it('does not publish a worker’s screen that comes back after a newer scene was traced inline', async () => {
    const newer = cheap(0.5);
    tracer.update(dear());
    await vi.advanceTimersByTimeAsync(0);
    tracer.update(newer);
    expect(published.map((rays) => rays.scene)).toEqual([newer]);
    await pool.answerAll();
    expect(published.map((rays) => rays.scene)).toEqual([newer]);
    expect(tracer.rays?.scene).toBe(newer);
    expect(pool.scenes).toHaveLength(1); // nothing was waiting for the worker
    expect(errors).toEqual([]);
  });

  it('traces a scene with a model in the worker until the model is loaded and its BVH built, then inline', async () => {
    const base = cheap();
    const withPrism = (x: number): Scene => ({
      ...base,
      objects: [...base.objects, { ...base.objects[1], id: 'prism', shape: 'mesh', mesh: 'prism', position: [x, 0.5, 2] }],
    });
    tracer.update(withPrism(0.5));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(pool.scenes).toHaveLength(1);
    expect(published).toHaveLength(1);
    expect(idle).toHaveLength(1); // the prism's BVH waits for an idle moment
    tracer.update(withPrism(0.6));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(pool.scenes).toHaveLength(2);
    idle.splice(0).forEach((build) => build());
    const later = withPrism(0.7);
    tracer.update(later);
    expect(published.at(-1)?.scene).toBe(later);
    expect(pool.scenes).toHaveLength(2);
  });

  it('reports an inline trace that throws, and publishes nothing for it', () => {
    vi.spyOn(inline, 'trace').mockImplementation(() => {
      throw new Error('inline bug');
    });
    tracer.update(cheap());
    expect(errors.map((error) => error.message)).toEqual(['inline bug']);
    expect(published).toEqual([]);
  });
});

/** Resolves with the next published screen. */
function nextRays(tracer: ScreenTracer): Promise<ScreenRays> {
  return new Promise((resolve) => {
    const unsubscribe = tracer.subscribe((rays) => {
      unsubscribe();
      resolve(rays);
    });
  });
}

describe('ScreenTracer with a worker thread', () => {
  it('publishes exactly the ray trees the tracer core gives for each pixel (models included)', async () => {
    const base = defaultScene();
    const scene: Scene = {
      ...base,
      camera: { ...base.camera, pixels: [4, 3] },
      objects: [...base.objects, { ...base.objects[1], id: 'prism', shape: 'mesh', mesh: 'prism', position: [0.5, 0.5, 2] }],
    };
    const pool = createNodeRenderPool(1);
    const tracer = new ScreenTracer(pool, loadMeshesFromDisk);
    try {
      const published = nextRays(tracer);
      tracer.update(scene);
      const rays = await published;
      const core = buildTracerScene(scene, await loadMeshesFromDisk(['prism']));
      expect([rays.columns, rays.rows]).toEqual([4, 3]);
      for (let y = 0; y < 3; y++) {
        for (let x = 0; x < 4; x++) expect(rays.traces[y * 4 + x]).toEqual(tracePixel(core, x, y, DEFAULT_SEED));
      }
      expect(rays.traces.some((trace) => trace.rays[0].children.length > 0)).toBe(true);
      // The debugger's pixel: the same tree, with its shading terms.
      expect(await tracer.traceWithTerms(1, 2)).toEqual(tracePixel(core, 1, 2, DEFAULT_SEED, { terms: true }));
    } finally {
      tracer.dispose();
      pool.dispose();
    }
  });

  it('reports a worker that dies to onError', async () => {
    const crashing = pathToFileURL(new URL('../support/crashing-worker.ts', import.meta.url).pathname).href;
    const pool = new RenderPool({ size: 1, createWorker: (handlers) => createNodeWorkerPort(handlers, crashing) });
    const tracer = new ScreenTracer(pool, noMeshes);
    try {
      const failed = new Promise<Error>((resolve) => (tracer.onError = resolve));
      tracer.update(sceneWithPixels(2, 2));
      expect((await failed).message).toMatch(/crashed on purpose/);
      expect(tracer.rays).toBeNull();
    } finally {
      tracer.dispose();
      pool.dispose();
    }
  });
});
