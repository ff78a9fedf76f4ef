/**
 * Measures what a sample of a scene costs on this machine, for the time estimate
 * (measured-estimate.ts): the workers trace a small image of the scene at one sample per
 * pixel, about PROBE_SECONDS of work by the model's guess, and report their rays and time.
 *
 * They trace it again until two rounds take about as long (STEADY): the first round can be
 * many times slower than the render will be, as workers that have not traced this kind of
 * scene yet run its code unoptimized until the engine has compiled it, on a busy machine for
 * seconds. From that steady pair on, rounds add up until they have taken MEASURED_MS, and
 * together they price a sample: a single short round catches the machine's other work in a
 * burst or a lull (at most MAX_PROBE_ROUNDS rounds in all, and after the second none begun
 * after MAX_PROBE_MS). Figures: docs/performance.md, "Cold code".
 */
import type { MeshLibrary } from '../scene/mesh-data.ts';
import type { Scene } from '../scene/scene.ts';
import { measuredEstimate, type SampleCost } from './measured-estimate.ts';
import {
  estimateRender,
  HEAVY_RENDER_SECONDS,
  modelEstimate,
  primaryRaysPerSample,
  RAYS_PER_SECOND_PER_WORKER,
  raysPerSample,
  type EstimateRender,
} from './render-estimate.ts';
import type { RenderPool } from './render-pool.ts';
import type { EstimateCalibration } from './estimate-calibration.ts';
import { raysOf } from './render-work.ts';

/**
 * A probe round's wall time by the model (with all workers): a few thousand samples of a
 * scene of 10 to 1000 rays per sample, a wait the learner hardly notices before a render of minutes.
 */
export const PROBE_SECONDS = 0.15;

/** Rounds whose times differ by less than this factor show the workers at their pace. */
const STEADY = 1.15;
/** The steady rounds' wall time that prices a sample. */
const MEASURED_MS = 600;
const MAX_PROBE_ROUNDS = 10;
/**
 * The longest the learner waits for "Estimating how long it takes…": on a machine busy with
 * other work each round takes many times the model's guess (in the project's browser tests
 * with nine other programs running, ten rounds took over 20 s); then the rounds so far price
 * the sample (two at least).
 */
const MAX_PROBE_MS = 3000;

/**
 * Renders the model puts under this are not probed: they start at once. The model's rays
 * are 0.7 to 3 times the real ones and its rate is on the slow side, so one it puts at
 * 6 s would have to be ten times slower to reach HEAVY_RENDER_SECONDS.
 */
export const PROBE_ABOVE_SECONDS = HEAVY_RENDER_SECONDS / 10;

/** Whether the model puts a render over PROBE_ABOVE_SECONDS, so that it is probed before it starts. */
export function mayBeLong(scene: Scene, width: number, height: number, workers: number): boolean {
  return estimateRender(scene, width, height, workers).seconds >= PROBE_ABOVE_SECONDS;
}

/** The probe's image for a `width × height` render on `workers` workers: the same aspect ratio, PROBE_SECONDS of samples or the whole image, at least one pixel. */
export function probeSize(scene: Scene, width: number, height: number, workers: number): [number, number] {
  const samples = (PROBE_SECONDS * RAYS_PER_SECOND_PER_WORKER * Math.max(1, workers)) / (raysPerSample(scene) * primaryRaysPerSample(scene));
  const scale = Math.min(1, Math.sqrt(samples / (width * height)));
  return [Math.max(1, Math.round(width * scale)), Math.max(1, Math.round(height * scale))];
}

/**
 * Traces the probe's rounds (see the file comment) and sums those from the first steady pair
 * on, or the last round when none was steady; null when it was cancelled (another render
 * started on the pool) or `signal` aborted it, which stops it before its next round.
 */
export async function probeSampleCost(
  pool: RenderPool,
  scene: Scene,
  meshes: MeshLibrary,
  width: number,
  height: number,
  signal?: AbortSignal,
): Promise<SampleCost | null> {
  const [probeWidth, probeHeight] = probeSize(scene, width, height, pool.size);
  const rounds: SampleCost[] = [];
  /** Where the steady rounds begin, once two in a row took about as long. */
  let steadyFrom = -1;
  const started = performance.now();
  // Two rounds at least, to see whether the pace is steady.
  while (rounds.length < 2 || (rounds.length < MAX_PROBE_ROUNDS && performance.now() - started < MAX_PROBE_MS)) {
    if (signal?.aborted) return null;
    const result = await pool.render(scene, meshes, { width: probeWidth, height: probeHeight, preview: false, oneSample: true }).done;
    if (result.cancelled) return null;
    // The wall time from the first tile's request, without a scene build the workers did first.
    rounds.push({ samples: probeWidth * probeHeight, rays: raysOf(result.stats), ms: Math.max(1, result.ms - result.sceneMs) });
    const [before, last] = rounds.slice(-2);
    if (steadyFrom < 0 && last && Math.max(last.ms / before.ms, before.ms / last.ms) < STEADY) steadyFrom = rounds.length - 2;
    if (steadyFrom >= 0 && sum(rounds.slice(steadyFrom)).ms >= MEASURED_MS) break;
  }
  return sum(rounds.slice(steadyFrom >= 0 ? steadyFrom : -1));
}

function sum(rounds: SampleCost[]): SampleCost {
  return rounds.reduce((total, round) => ({ samples: total.samples + round.samples, rays: total.rays + round.rays, ms: total.ms + round.ms }), {
    samples: 0,
    rays: 0,
    ms: 0,
  });
}

export interface EstimateHereOptions {
  /** Previews before the final pass (the render window) or not (`rt render`). */
  preview: boolean;
  /** How this session's estimates compared with its renders' real times. */
  calibration: EstimateCalibration;
  /** Aborted when the estimate is no longer wanted (the learner rendered anyway): the probe stops. */
  signal?: AbortSignal;
}

/** Estimates of a render and its lighter variants, and whether a probe measured them. */
export interface EstimatesHere {
  estimate: EstimateRender;
  /** True when priced by a probe on this machine; false for the model's (a render it puts under PROBE_ABOVE_SECONDS). */
  measured: boolean;
}

/**
 * Estimates of a `width × height` render of `scene` and its lighter variants on this
 * machine: the model's when it puts the render under PROBE_ABOVE_SECONDS (no wait), else
 * measured by a probe. Null when the probe was cancelled.
 */
export async function estimateHere(
  pool: RenderPool,
  scene: Scene,
  meshes: MeshLibrary,
  width: number,
  height: number,
  { preview, calibration, signal }: EstimateHereOptions,
): Promise<EstimatesHere | null> {
  if (!mayBeLong(scene, width, height, pool.size)) return { estimate: modelEstimate(pool.size), measured: false };
  const cost = await probeSampleCost(pool, scene, meshes, width, height, signal);
  return cost && { estimate: measuredEstimate(cost, scene, { workers: pool.size, preview, correction: calibration.correction }), measured: true };
}
