import type { MeshData, MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import type { Scene } from '../scene/scene.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import { hasMeshAccel, meshAccel } from '../tracer/shapes/mesh-accel.ts';
import { labPaths, type LabPaths } from '../tracer/lab-paths.ts';
import { tracePixel, tracePixels } from '../tracer/trace-pixel.ts';
import { buildTracerScene, type TracerScene } from '../tracer/tracer-scene.ts';
import { estimateRender } from './render-estimate.ts';
import { DEFAULT_SEED } from './render-job.ts';
import type { ScreenRays } from './screen-rays.ts';

/**
 * The most rays (as render-estimate.ts counts them) a screen may cost to be traced on the
 * main thread. The free lab's 16 × 16 screen is estimated at 1088 rays and traces in
 * 4.5 ms (warm) on a 2.45 GHz Zen 3 core, so this is about 8 ms there: half a 60 Hz frame.
 * Every level's own screen is estimated at 24 to 915 rays.
 */
export const INLINE_RAY_BUDGET = 2048;

/** Runs `callback` when the main thread is idle (after the next frame), or in a later task where there is no such notion (Node). */
const whenIdle: (callback: () => void) => void =
  typeof requestIdleCallback === 'function' ? (callback) => void requestIdleCallback(callback, { timeout: 1000 }) : (callback) => void setTimeout(callback, 0);

/**
 * Traces a small screen where it is called, synchronously: the lab's screen tracer calls it
 * inside the edit's own event, so the edit's rays are drawn in the same frame as the edit
 * (the slider's new position), not one frame later. Through a worker they came back 10–20 ms
 * after the event, after the browser had started the frame that shows the slider: a drag on
 * SwiftShader then took two frames a step (p95 170–225 ms against the ≤ 100 ms goal;
 * docs/benchmark-log.md). Only cheap screens (INLINE_RAY_BUDGET) whose models' BVHs are built
 * already come here; the rest, and every full render, stay in the workers.
 *
 * The trees are the worker's to the bit: the same tracePixels with the same seed.
 */
export class InlineScreenTracer {
  /** The scene last traced here, built: the ray debugger's pixel is traced in it. */
  private built: TracerScene | null = null;
  /** Models whose BVH prepare has asked to build in an idle moment (never inside an edit). */
  private readonly preparing = new WeakSet<MeshData>();

  constructor(private readonly idle: (callback: () => void) => void = whenIdle) {}

  /** Whether `scene`'s screen is cheap enough to trace here, with every model it uses in `models` and its BVH built (by prepare, or by the BVH view). */
  affords(scene: Scene, models: MeshLibrary): boolean {
    const [columns, rows] = scene.camera.pixels;
    if (estimateRender(scene, columns, rows).rays > INLINE_RAY_BUDGET) return false;
    return meshNamesInScene(scene).every((name) => {
      const mesh = models.get(name);
      return mesh !== undefined && hasMeshAccel(mesh);
    });
  }

  /**
   * Builds the models' BVHs when the main thread is idle (a model's first build can take
   * 30–90 ms, too long for an edit's event); scenes that use them are affordable from then on.
   */
  prepare(models: MeshLibrary): void {
    for (const mesh of models.values()) {
      if (hasMeshAccel(mesh) || this.preparing.has(mesh)) continue;
      this.preparing.add(mesh);
      this.idle(() => meshAccel(mesh));
    }
  }

  /** Every pixel of `scene`'s screen, now. Throws as buildTracerScene and tracePixel do. */
  trace(scene: Scene, models: MeshLibrary): ScreenRays {
    const built = buildTracerScene(scene, models);
    const [columns, rows] = scene.camera.pixels;
    const traces = tracePixels(built, 0, columns * rows, DEFAULT_SEED);
    this.built = built;
    return { columns, rows, traces, scene };
  }

  /** Pixel (x, y)'s tree with every hit's shading terms, in the scene last traced here. */
  traceWithTerms(x: number, y: number): PixelTrace {
    if (!this.built) throw new Error('no screen has been traced here yet');
    return tracePixel(this.built, x, y, DEFAULT_SEED, { terms: true });
  }

  /** Pixel (x, y)'s first `keep` paths in path mode, in the scene last traced here. */
  tracePaths(x: number, y: number, keep: number): LabPaths {
    if (!this.built) throw new Error('no screen has been traced here yet');
    return labPaths(this.built, x, y, DEFAULT_SEED, keep);
  }
}
