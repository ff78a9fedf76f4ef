import type { Vector3 } from 'three';
import type { PrimaryCandidates } from './primary-candidates.ts';
import type { Ray } from './ray.ts';
import type { RayStats } from './ray-tree.ts';

/**
 * One way of estimating the light that arrives along a camera ray: pbrt-v4's
 * `RayIntegrator::Li`, which the pixel loop (renderPixel: supersamples, lens, shutter) calls
 * once per primary ray. Whitted's recursive tracer (whitted-integrator.ts) is one; a path
 * tracer (Kajiya 1986; the path-tracing spec's `settings.integrator: "path"`) is another,
 * beside it, with its own recorder (a sample's paths, vertex by vertex, where
 * Whitted records a ray tree).
 *
 * Every random number an estimator draws is keyed by the pixel sample it belongs to (the
 * start… calls), never by the order pixels are traced in: so a recorded pixel re-creates
 * exactly what the image averaged, and tiles can be traced by any worker in any order.
 *
 * @typeParam Recorder what records a traced ray for the lab and `rt trace`; rendering passes null
 */
export interface Estimator<Recorder> {
  /** Rays cast so far, by kind (`rt render --stats`, the benchmark); the caller resets them. */
  readonly stats: RayStats;
  /** The side of a pixel at distance 1 from the eye in the image being rendered (CameraRays.pixelSpread). */
  pixelSpread: number;
  /** The objects the primary rays of the tile being rendered can hit (renderTile); null: they walk the BVH. */
  primaryCandidates: PrimaryCandidates | null;
  /** Keys the random numbers of the coming pixel sample by (seed, pixel, sample); its rays are at time 0. */
  startPixelSample(seed: number, x: number, y: number, sample: number): void;
  /** Keys the random numbers of one lens/time ray of the current pixel sample, traced at `time` (τ in [0, 1)). */
  startSubSample(seed: number, x: number, y: number, sample: number, subSample: number, time: number): void;
  /** Li: the colour seen along the primary ray `ray`, written into `out` (and returned). */
  li(ray: Ray, out: Vector3, recorder: Recorder | null): Vector3;
}
