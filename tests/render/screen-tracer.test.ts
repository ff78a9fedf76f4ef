import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { pathToFileURL } from 'node:url';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { RenderPool } from '../../src/render/render-pool.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { ScreenTracer, TRACES_IN_FLIGHT, type ScreenTracePool } from '../../src/render/screen-tracer.ts';
import { createNodeRenderPool, createNodeWorkerPort } from '../../src/cli/node-worker-port.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

const NO_MESHES: MeshLibrary = new Map();
const noMeshes = () => Promise.resolve(NO_MESHES);

function sceneWithPixels(columns: number, rows: number): Scene {
  const scene = defaultScene();
  return { ...scene, camera: { ...scene.camera, pixels: [columns, rows] } };
}

interface Request {
  scene: Scene;
  x: number;
  y: number;
  seed: number | undefined;
  resolve(trace: PixelTrace): void;
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

  tracePixel(x: number, y: number, seed?: number): Promise<PixelTrace> {
    const scene = this.scenes[this.scenes.length - 1];
    return new Promise((resolve, reject) => {
      const request: Request = { scene, x, y, seed, resolve, reject };
      request.resolve = (trace) => (this.pending.delete(request), resolve(trace));
      request.reject = (error) => (this.pending.delete(request), reject(error));
      this.requests.push(request);
      this.pending.add(request);
    });
  }

  /** Answers every pending request (and those they lead to), letting the tracer's awaits run. */
  async answerAll(): Promise<void> {
    while (this.pending.size > 0) {
      for (const request of [...this.pending]) request.resolve({ pixel: [request.x, request.y], color: [request.x, request.y, 0], rays: [] });
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
    expect(rays.traces.map((trace) => trace.pixel)).toEqual([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1]]);
    expect(pool.requests.every((request) => request.seed === DEFAULT_SEED)).toBe(true);
    expect(tracer.rays).toBe(rays);
    expect(errors).toEqual([]);
  });

  it('traces a scene at once when idle; the trace that replaced a dropped one is kept, and only the newest scene waits for it', async () => {
    const scenes = [sceneWithPixels(1, 1), sceneWithPixels(2, 1), sceneWithPixels(2, 2), sceneWithPixels(3, 1)];
    tracer.update(scenes[0]);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([scenes[0]]);
    tracer.update(scenes[1]); // drops the first trace
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([scenes[0], scenes[1]]);
    tracer.update(scenes[2]);
    tracer.update(scenes[3]);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([scenes[0], scenes[1]]); // the kept trace runs on
    await pool.answerAll();
    // The kept trace published, then the newest scene was traced; the one in between never.
    expect(pool.scenes).toEqual([scenes[0], scenes[1], scenes[3]]);
    expect(published.map((rays) => rays.traces.length)).toEqual([2, 3]);
    expect(tracer.rays?.columns).toBe(3);
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

  it('keeps at most TRACES_IN_FLIGHT pixel requests waiting', async () => {
    tracer.update(sceneWithPixels(16, 16));
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.pending.size).toBe(TRACES_IN_FLIGHT);
    await pool.answerAll();
    expect(pool.requests).toHaveLength(256);
    expect(published[0].traces).toHaveLength(256);
  });

  it('latest wins: a newer scene drops the running trace at once, which stops requesting its pixels', async () => {
    const older = sceneWithPixels(16, 16);
    const newer = sceneWithPixels(2, 1);
    tracer.update(older);
    await vi.advanceTimersByTimeAsync(0);
    tracer.update(newer);
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.scenes).toEqual([older, newer]);
    await pool.answerAll(); // the old scene's requests come back late
    expect(pool.requests.filter((request) => request.scene === older)).toHaveLength(TRACES_IN_FLIGHT);
    expect(published).toHaveLength(1);
    expect([published[0].columns, published[0].rows]).toEqual([2, 1]);
  });

  it('reports a failed trace to onError once, and publishes nothing for that scene', async () => {
    tracer.update(sceneWithPixels(8, 8));
    await vi.advanceTimersByTimeAsync(0);
    const [first, second] = [...pool.pending];
    first.reject(new Error('worker died'));
    second.reject(new Error('worker died again'));
    await pool.answerAll();
    expect(errors.map((error) => error.message)).toEqual(['worker died']);
    expect(pool.requests).toHaveLength(TRACES_IN_FLIGHT);
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
