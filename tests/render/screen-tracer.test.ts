import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { pathToFileURL } from 'node:url';
import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { RenderPool } from '../../src/render/render-pool.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { PIXELS_PER_REQUEST, REQUESTS_IN_FLIGHT, ScreenTracer, type ScreenTracePool } from '../../src/render/screen-tracer.ts';
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

/** A request for pixels first … first + count - 1 of the screen. */
interface Request {
  scene: Scene;
  first: number;
  count: number;
  seed: number | undefined;
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

  tracePixels(first: number, count: number, seed?: number): Promise<PixelTrace[]> {
    const scene = this.scenes[this.scenes.length - 1];
    return new Promise((resolve, reject) => {
      const request: Request = { scene, first, count, seed, resolve, reject };
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
    expect(rays.traces.map((trace) => trace.pixel)).toEqual([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1]]);
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
    const blocks = Array.from({ length: Math.ceil(pixels / PIXELS_PER_REQUEST) }, (_, i) => [i * PIXELS_PER_REQUEST, Math.min(PIXELS_PER_REQUEST, pixels - i * PIXELS_PER_REQUEST)]);
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
    expect(published.map((rays) => [rays.columns, rays.rows])).toEqual([[16, 16], [2, 1]]);
  });

  it('reports a failed trace to onError once, and publishes nothing for that scene', async () => {
    // Twice as many blocks as may be in flight: none is asked for after the failure.
    tracer.update(sceneWithPixels(16, (2 * REQUESTS_IN_FLIGHT * PIXELS_PER_REQUEST) / 16));
    await vi.advanceTimersByTimeAsync(0);
    const [first, second] = [...pool.pending];
    first.reject(new Error('worker died'));
    second.reject(new Error('worker died again'));
    await vi.advanceTimersByTimeAsync(0);
    await pool.answerAll();
    expect(errors.map((error) => error.message)).toEqual(['worker died']);
    expect(pool.requests).toHaveLength(REQUESTS_IN_FLIGHT);
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
