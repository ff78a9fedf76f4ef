import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { RenderPool } from '../../src/render/render-pool.ts';
import type { CreateRenderWorker } from '../../src/render/render-worker-port.ts';
import type { ScreenRays } from '../../src/render/screen-rays.ts';
import { ScreenTracer, TRACE_RETRIES, type ScreenTracePool } from '../../src/render/screen-tracer.ts';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { LabPaths } from '../../src/tracer/lab-paths.ts';
import type { PixelTrace } from '../../src/tracer/ray-tree.ts';
import { createRenderHandler } from '../../workers/render-core.ts';
import type { RayBudget } from '../../workers/protocol.ts';

const NO_MESHES: MeshLibrary = new Map();
const noMeshes = () => Promise.resolve(NO_MESHES);

/** The default scene on a columns × rows screen, 2 × 2 supersampled so that a budget thins it. */
function sceneWithPixels(columns: number, rows: number): Scene {
  const scene = defaultScene();
  return { ...scene, camera: { ...scene.camera, pixels: [columns, rows] }, settings: { ...scene.settings, supersampling: 2 } };
}

const BUDGET: RayBudget = { rays: 40, keepPixel: 5 };

/**
 * In-process workers (the real handler, no thread); the first `silent` started never answer
 * pixel traces, as a worker that dies silently or outlasts the pool's deadline.
 */
function workersFallingSilent(silent: number): CreateRenderWorker {
  let started = 0;
  return ({ onResponse }) => {
    const isSilent = ++started <= silent;
    const handle = createRenderHandler((response) => {
      if (isSilent && response.type === 'pixels-traced') return;
      onResponse(response);
    });
    return { post: (request) => handle(request), terminate: () => {} };
  };
}

/** The first screen `tracer` publishes for `scene` with BUDGET, or its first error. */
function traceOnce(pool: RenderPool, scene: Scene): Promise<ScreenRays> {
  const tracer = new ScreenTracer(pool, noMeshes);
  return new Promise<ScreenRays>((resolve, reject) => {
    tracer.onError = reject;
    tracer.subscribe(resolve);
    tracer.setBudget(BUDGET);
    tracer.update(scene);
  }).finally(() => tracer.dispose());
}

describe('ScreenTracer when the pool replaces its worker mid-trace', () => {
  it('asks again, and the screen still gets every pixel’s rays, as a trace with no failure', async () => {
    const scene = sceneWithPixels(4, 3);
    const log: string[] = [];
    const watchdog = { floorMs: 400, sceneBuildMs: 30_000, checkEveryMs: 50 };
    const failing = new RenderPool({ size: 1, createWorker: workersFallingSilent(1), log: (message) => log.push(message), watchdog });
    const healthy = new RenderPool({ size: 1, createWorker: workersFallingSilent(0), watchdog });
    try {
      const expected = await traceOnce(healthy, scene);

      const rays = await traceOnce(failing, scene);
      expect(log).toEqual([expect.stringMatching(/stopped answering/)]);
      expect(rays.traces).toHaveLength(12);
      expect(rays.traces).toEqual(expected.traces);
    } finally {
      failing.dispose();
      healthy.dispose();
    }
  });
});

/** A pool whose every trace fails at once, counting the requests. */
class FailingPool implements ScreenTracePool {
  requests = 0;
  setScene(): void {}
  tracePixel(): Promise<PixelTrace> {
    return Promise.reject(new Error('not used'));
  }
  tracePaths(): Promise<LabPaths> {
    return Promise.reject(new Error('not used'));
  }
  tracePixels(): Promise<PixelTrace[]> {
    this.requests++;
    return Promise.reject(new Error(`worker replaced (${this.requests})`));
  }
}

describe('ScreenTracer retries (fake pool)', () => {
  let pool: FailingPool;
  let tracer: ScreenTracer;
  let errors: string[];

  beforeEach(() => {
    vi.useFakeTimers();
    pool = new FailingPool();
    tracer = new ScreenTracer(pool, noMeshes);
    errors = [];
    tracer.onError = (error) => errors.push(error.message);
  });

  afterEach(() => {
    tracer.dispose();
    vi.useRealTimers();
  });

  it('asks a failing block TRACE_RETRIES times more, then reports the last failure once', async () => {
    tracer.update(sceneWithPixels(2, 2));
    await vi.advanceTimersByTimeAsync(0);
    expect(pool.requests).toBe(1 + TRACE_RETRIES);
    expect(errors).toEqual([`worker replaced (${1 + TRACE_RETRIES})`]);
    expect(tracer.rays).toBeNull();
  });

  it('does not ask again for a screen a newer scene replaced: the newer one is traced', async () => {
    tracer.update(sceneWithPixels(2, 2));
    tracer.update(sceneWithPixels(3, 2)); // arrives while the first trace's block is asked
    await vi.advanceTimersByTimeAsync(0);
    // The first screen's block once, then the newer one's with its own tries.
    expect(pool.requests).toBe(1 + 1 + TRACE_RETRIES);
    expect(errors).toHaveLength(1);
  });
});
