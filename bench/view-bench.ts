/**
 * The lab view's part of `npm run bench` (issue: the 3D lab, "Performance"): the ray pool's
 * draw calls at 1k, 10k and 50k rays (they must not grow), the time to rebuild it for 10k
 * rays (goal ≤ 2 ms), its instance-buffer memory, hover picking at 50k rays, and how long
 * the screen tracer takes to trace a 16×16 screen in its one worker. Runs in Node: three.js
 * objects work without WebGL; what the GPU then does with the buffers is not measured here
 * (the e2e run records the browser's long tasks).
 */
import { Raycaster, Vector3 } from 'three';
import { DEFAULT_RAY_VIEW } from '../src/lab-state/lab-state.ts';
import type { ScreenRays } from '../src/render/screen-rays.ts';
import { ScreenTracer } from '../src/render/screen-tracer.ts';
import { createNodeRenderPool } from '../src/cli/node-worker-port.ts';
import { loadMeshesFromDisk } from '../src/scene/load-meshes-node.ts';
import { defaultScene } from '../src/scene/scene-defaults.ts';
import { RayPool } from '../src/view/ray-pool.ts';
import { syntheticScreen } from '../tests/support/ray-fixtures.ts';
import { median } from './median.ts';

const SIZES = [1_000, 10_000, 50_000] as const;
/** Timed repetitions per figure; the median is reported (robust to a GC pause or another process). */
const REPEATS = 31;

export interface ViewBenchResults {
  drawCalls: Record<string, number>;
  /**
   * Median ms for RayPool.update after an option change (a slider drag): the visibility
   * rules over the flattened trees and the instance buffers, with 10k and 50k rays.
   */
  rebuildMs: Record<string, number>;
  /** Median ms for RayPool.update with a newly traced screen of 10k rays (flattening its trees too). */
  newRays10kMs: number;
  /** Per-instance buffer bytes at each size (pooled capacity, both meshes). */
  instanceBytes: Record<string, number>;
  /** Median ms of one RayPool.pick over 50k rays (done at most once per frame on hover). */
  pick50kMs: number;
  /** Camera screen 16×16 of the default scene, traced by the screen tracer's one worker. */
  screenTrace16x16Ms: number;
}

function timeMedian(run: (i: number) => void): number {
  run(0); // warm-up: the JIT and the pooled buffers' first growth
  return median(
    Array.from({ length: REPEATS }, (_, i) => {
      const started = performance.now();
      run(i + 1);
      return performance.now() - started;
    }),
  );
}

/** A pointer ray from the usual lab viewpoint through the middle of the synthetic rays. */
function labPointer(): Raycaster {
  const eye = new Vector3(4.5, 3.6, 6.5);
  return new Raycaster(eye, new Vector3(0, 0.5, 0).sub(eye).normalize());
}

/** Time from a scene change to the published ScreenRays (an idle tracer starts at once). */
async function timeScreenTrace(): Promise<number> {
  const pool = createNodeRenderPool(1);
  const tracer = new ScreenTracer(pool, loadMeshesFromDisk);
  /** Resolves with the next screen published after now (subscribe also replays the last one at once). */
  const traced = () =>
    new Promise<void>((resolve, reject) => {
      const before = tracer.rays;
      tracer.onError = reject;
      const stop = tracer.subscribe((rays) => {
        if (rays === before) return;
        queueMicrotask(() => stop());
        resolve();
      });
    });
  try {
    const base = defaultScene();
    // Warm-up: the worker starts and compiles the tracer.
    const warm = traced();
    tracer.update({ ...base, camera: { ...base.camera, pixels: [16, 16] } });
    await warm;
    const times: number[] = [];
    for (let i = 0; i < 5; i++) {
      const next = traced();
      const started = performance.now();
      tracer.update({ ...base, camera: { ...base.camera, pixels: [16, 16], fov: 45 + i } });
      await next;
      times.push(performance.now() - started);
    }
    return median(times);
  } finally {
    tracer.dispose();
    pool.dispose();
  }
}

export async function measureView(): Promise<ViewBenchResults> {
  const screens = new Map<number, ScreenRays>(SIZES.map((size) => [size, syntheticScreen(size)]));
  const drawCalls: Record<string, number> = {};
  const instanceBytes: Record<string, number> = {};
  const rebuildMs: Record<string, number> = {};
  for (const size of SIZES) {
    const pool = new RayPool();
    const rays = screens.get(size) as ScreenRays;
    // Alternating an option, as a slider drag does: every update really rewrites the buffers.
    const ms = timeMedian((i) => pool.update(rays, { ...DEFAULT_RAY_VIEW, transparency: (i % 2) * 0.3 }, null));
    drawCalls[size] = pool.stats.drawCalls;
    instanceBytes[size] = pool.stats.instanceBytes;
    if (size !== 1_000) rebuildMs[size] = ms;
    pool.dispose();
  }

  const pool = new RayPool();
  const fresh = Array.from({ length: REPEATS + 1 }, () => syntheticScreen(10_000));
  const newRays10kMs = timeMedian((i) => pool.update(fresh[i], DEFAULT_RAY_VIEW, null));
  pool.update(screens.get(50_000) as ScreenRays, DEFAULT_RAY_VIEW, null);
  const pointer = labPointer();
  const pick50kMs = timeMedian(() => pool.pick(pointer));
  pool.dispose();

  return { drawCalls, rebuildMs, newRays10kMs, instanceBytes, pick50kMs, screenTrace16x16Ms: await timeScreenTrace() };
}

const round = (value: number, digits = 2) => Number(value.toFixed(digits));

/** The results rounded for bench/results.json. */
export function roundedView(results: ViewBenchResults): ViewBenchResults {
  const each = (record: Record<string, number>) => Object.fromEntries(Object.entries(record).map(([k, v]) => [k, round(v)]));
  return {
    drawCalls: results.drawCalls,
    rebuildMs: each(results.rebuildMs),
    newRays10kMs: round(results.newRays10kMs),
    instanceBytes: results.instanceBytes,
    pick50kMs: round(results.pick50kMs),
    screenTrace16x16Ms: round(results.screenTrace16x16Ms, 1),
  };
}

/** Rows of [measure, value, goal] for the benchmark's table. */
export function viewRows(results: ViewBenchResults): [string, string, string][] {
  const mb = (bytes: number) => `${(bytes / 1e6).toFixed(2)} MB`;
  return [
    ['ray draw calls at 1k / 10k / 50k rays', SIZES.map((size) => results.drawCalls[size]).join(' / '), 'constant'],
    ['ray pool rebuild after an option change, 10k rays', `${round(results.rebuildMs[10_000])} ms`, '≤ 2 ms'],
    ['ray pool rebuild after an option change, 50k rays', `${round(results.rebuildMs[50_000])} ms`, '< 16 ms (a frame)'],
    ['ray pool build for newly traced 10k rays', `${round(results.newRays10kMs)} ms`, ''],
    ['ray instance buffers at 1k / 10k / 50k', SIZES.map((size) => mb(results.instanceBytes[size])).join(' / '), ''],
    ['ray hover pick, 50k rays', `${round(results.pick50kMs)} ms`, '< 16 ms (a frame)'],
    ['camera screen 16×16 traced (1 worker)', `${round(results.screenTrace16x16Ms, 1)} ms`, ''],
  ];
}
