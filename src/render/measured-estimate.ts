/**
 * A render's time from what a sample of its scene costs on this machine, measured (issue
 * 37: "313 × 313 (about 60 s)" took 2 min 31 s).
 *
 * The model of render-estimate.ts counts rays from the scene's make-up, with a guessed
 * chance that a reflected ray hits something, and prices every ray alike at an assumed rate.
 * Both guesses are off by more than the 1.5 we allow, and differently for every scene: the
 * levels' scenes come out at 0.7 to 3 times the rays they trace, a shadow ray towards a
 * point light costs a fraction of a primary ray into a model of 8,624 triangles, and a school
 * laptop is not the machine the rate was measured on.
 *
 * So before a render that may be long, the workers trace a small image of the same scene at
 * one sample per pixel (render-probe.ts), spread over the whole picture like the render's
 * coarse preview: a few thousand samples, traced again until the workers' pace is steady,
 * in a fraction of a second on a quiet machine. Every sample of the render costs, on
 * average, what a probe sample cost: each is a primary ray (n² lens rays, k shutter times)
 * with all its shadow, reflected and refracted rays, through the same scene on the same
 * workers; supersampling only adds samples. The probe's wall time, not its workers' time,
 * prices a sample: it is what the render's samples will take with all the workers, on a
 * machine that has the cores to run them side by side or not (on the project's busy 2-core
 * machine the probe's workers' time added up to its wall time: one worker's worth of cores).
 * The estimate is then
 *
 *     seconds = (samples of all the render's passes) × (probe's wall ms per sample) × correction
 *
 * where the passes are the previews, the sharp one-sample pass and the final pass at s²
 * samples per pixel (render-passes.ts), and the correction is the real time per estimated
 * time of this session's long renders (estimate-calibration.ts). A lighter render of the
 * same scene is priced from the same probe: fewer samples or pixels cost proportionally
 * less; a shallower ray tree scales the cost per sample by the model's ratio of rays per
 * sample, the one part that is not measured.
 */
import type { Scene } from '../scene/scene.ts';
import { HEAVY_RENDER_SECONDS, primaryRaysPerSample, raysPerSample, type EstimateRender } from './render-estimate.ts';
import { planPasses, tracedSamples } from './render-passes.ts';

/** What the probe traced: its samples, their rays, and its wall time (ms, with all the workers). */
export interface SampleCost {
  samples: number;
  rays: number;
  ms: number;
}

export interface MeasuredEstimateOptions {
  /** The pool's workers, who traced the probe and will trace the render (the first preview's block depends on them). */
  workers: number;
  /** Whether the render makes previews first (the render window) or only its final pass (`rt render`). */
  preview: boolean;
  /** Real time per estimated time of this session's renders (estimate-calibration.ts); 1 when nothing is known. */
  correction: number;
}

/** The model's rays of one sample: what a variant of the probed scene costs relative to it. */
function modelRaysPerSample(scene: Scene): number {
  return raysPerSample(scene) * primaryRaysPerSample(scene);
}

/** Estimates of renders of `probed` and its lighter variants, priced by `cost`, measured on `probed`. */
export function measuredEstimate(cost: SampleCost, probed: Scene, { workers, preview, correction }: MeasuredEstimateOptions): EstimateRender {
  const msPerSample = cost.ms / Math.max(1, cost.samples);
  const raysPerProbeSample = cost.rays / Math.max(1, cost.samples);
  return (scene, width, height) => {
    // 1 for other sizes and supersampling; the model's ratio for another depth.
    const relative = modelRaysPerSample(scene) / modelRaysPerSample(probed);
    const image = { x: 0, y: 0, width, height };
    const passes = planPasses(scene, { width, height, workers, preview });
    const samples = passes.reduce((sum, pass) => sum + tracedSamples(image, pass), 0);
    // The image's samples: the final pass's, or in path mode the paths of all its refining passes (path-passes.ts).
    const finalSamples = passes.reduce((sum, pass) => sum + (pass.kind === 'final' ? tracedSamples(image, pass) : 0), 0);
    const rays = finalSamples * raysPerProbeSample * relative;
    const seconds = (samples * msPerSample * relative * correction) / 1000;
    return { rays, raysPerPixel: rays / (width * height), seconds, heavy: seconds > HEAVY_RENDER_SECONDS };
  };
}
