import { afterAll, afterEach, describe, expect, it, vi } from 'vitest';
import { createNodeRenderPool } from '../../src/cli/node-worker-port.ts';
import { estimateRender, primaryRaysPerSample, RAYS_PER_SECOND_PER_WORKER, raysPerSample } from '../../src/render/render-estimate.ts';
import { estimateHere, PROBE_ABOVE_SECONDS, PROBE_SECONDS, probeSampleCost, probeSize } from '../../src/render/render-probe.ts';
import type { RenderOptions } from '../../src/render/render-job.ts';
import type { RenderPool } from '../../src/render/render-pool.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { EstimateCalibration } from '../../src/render/estimate-calibration.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { sceneFrom } from '../support/test-scene.ts';

const NO_MESHES = new Map();
const pool = createNodeRenderPool(2);
afterAll(() => pool.dispose());
afterEach(() => vi.restoreAllMocks());

const withSettings = (settings: Partial<Scene['settings']>): Scene => sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, ...settings } });

describe('the probe before a render that may be long', () => {
  it('is a small image of the same aspect, about PROBE_SECONDS of samples by the model, never larger than the image', () => {
    const scene = withSettings({ supersampling: 8 });
    const [width, height] = probeSize(scene, 4096, 3072, 2);
    expect(width / height).toBeCloseTo(4 / 3, 1);
    const seconds = (width * height * raysPerSample(scene) * primaryRaysPerSample(scene)) / (2 * RAYS_PER_SECOND_PER_WORKER);
    expect(seconds).toBeGreaterThan(0.9 * PROBE_SECONDS);
    expect(seconds).toBeLessThan(1.1 * PROBE_SECONDS);
    expect(probeSize(defaultScene(), 40, 30, 2)).toEqual([40, 30]);
    expect(probeSize(withSettings({ maxDepth: 10 }), 1, 1, 1)).toEqual([1, 1]);
  });

  it('is left out for a render the model puts well under a minute: it starts at once', async () => {
    const render = vi.spyOn(pool, 'render');
    const scene = defaultScene();
    const [width, height] = scene.settings.imageSize;
    expect(estimateRender(scene, width, height, pool.size).seconds).toBeLessThan(PROBE_ABOVE_SECONDS);
    const estimate = await estimateHere(pool, scene, NO_MESHES, width, height, { preview: true, calibration: new EstimateCalibration() });
    expect(estimate?.measured).toBe(false);
    expect(estimate?.estimate(scene, width, height).heavy).toBe(false);
    expect(render).not.toHaveBeenCalled();
  });

  it('traces one sample per pixel of the small image for a long render, and calls it heavy', async () => {
    const render = vi.spyOn(pool, 'render');
    const scene = withSettings({ supersampling: 8, imageSize: [4096, 4096] });
    const estimate = await estimateHere(pool, scene, NO_MESHES, 4096, 4096, { preview: true, calibration: new EstimateCalibration() });
    const [width, height] = probeSize(scene, 4096, 4096, pool.size);
    // At least two rounds, to see the workers' pace steady; at most ten.
    expect(render.mock.calls.length).toBeGreaterThanOrEqual(2);
    expect(render.mock.calls.length).toBeLessThanOrEqual(10);
    for (const call of render.mock.calls) expect(call).toEqual([scene, NO_MESHES, { width, height, preview: false, oneSample: true }]);
    expect(estimate?.measured).toBe(true);
    const full = estimate!.estimate(scene, 4096, 4096);
    expect(full.heavy).toBe(true);
    // Each of the 4096² × 64 samples of the final pass costs a primary ray at least.
    expect(full.rays).toBeGreaterThan(4096 * 4096 * 64);
  });

  /** A pool whose renders take `ms` in turn, 10 rays a sample. */
  function poolTaking(...ms: number[]): { pool: RenderPool; rounds: () => number } {
    let round = 0;
    const stub = {
      size: 2,
      render: (_scene: Scene, _meshes: unknown, { width = 1, height = 1 }: RenderOptions) => ({
        done: Promise.resolve({ cancelled: false, stats: { ...emptyRayStats(), primary: 10 * width * height }, ms: ms[round++], sceneMs: 0 }),
      }),
    };
    return { pool: stub as unknown as RenderPool, rounds: () => round };
  }

  it('traces again until two rounds take about as long, then sums the rounds from there until they took 600 ms', async () => {
    const scene = withSettings({ supersampling: 8 });
    const [width, height] = probeSize(scene, 4096, 4096, 2);
    // The first rounds run code V8 has not optimized yet.
    const cold = poolTaking(900, 300, 110, 100, 100, 100, 100, 100, 100);
    const cost = await probeSampleCost(cold.pool, scene, NO_MESHES, 4096, 4096);
    expect(cold.rounds()).toBe(8);
    expect(cost).toEqual({ samples: 6 * width * height, rays: 60 * width * height, ms: 610 });
    // Slow rounds: the steady pair is enough.
    const warm = poolTaking(400, 410, 50);
    expect((await probeSampleCost(warm.pool, scene, NO_MESHES, 4096, 4096))?.ms).toBe(810);
    expect(warm.rounds()).toBe(2);
    // Never steady: the last of ten rounds.
    const restless = poolTaking(100, 200, 100, 200, 100, 200, 100, 200, 100, 200, 100);
    expect((await probeSampleCost(restless.pool, scene, NO_MESHES, 4096, 4096))?.ms).toBe(200);
    expect(restless.rounds()).toBe(10);
  });

  it('stops before its next round when it is no longer wanted', async () => {
    const controller = new AbortController();
    const stub = poolTaking(900, 300, 100, 100);
    const probing = probeSampleCost(stub.pool, withSettings({ supersampling: 8 }), NO_MESHES, 4096, 4096, controller.signal);
    controller.abort();
    expect(await probing).toBeNull();
    expect(stub.rounds()).toBe(1);
  });

  it('says nothing when another render overtakes it', async () => {
    const scene = withSettings({ supersampling: 8, imageSize: [4096, 4096] });
    const estimating = estimateHere(pool, scene, NO_MESHES, 4096, 4096, { preview: true, calibration: new EstimateCalibration() });
    await Promise.resolve();
    const next = pool.render(defaultScene(), NO_MESHES, { width: 8, height: 8 });
    expect(await estimating).toBeNull();
    expect((await next.done).cancelled).toBe(false);
  });
});
