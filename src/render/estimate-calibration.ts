/**
 * How this session's measured estimates compared with the renders they promised: the time
 * estimate (measured-estimate.ts) is multiplied by the real time per estimated time of the
 * long renders so far. The probe prices a sample well, but a render is not only its samples:
 * each tile is a message each way, the page paints the picture on the same cores, and the
 * last tiles of a pass leave a worker idle; on a machine where that costs a tenth more,
 * the second long render is promised a tenth more than the first.
 */

/** Renders estimated at less than this are not counted: their fixed costs (the first messages, the raster picture) say nothing of a long render. */
const MIN_ESTIMATED_SECONDS = 5;

/**
 * The correction starts as if one render of a minute had come out as estimated: one render
 * on a busy machine is as much the load of that minute as the machine's bias (the benchmark's
 * first case once took 0.59 times its estimate, and the next case, corrected by that, 1.77
 * times), so it moves the correction part of the way, and many renders all of it.
 */
const PRIOR_SECONDS = 60;

/** The correction stays within this factor either way: a render stalled by something else (a laptop's sleep) must not make every later estimate absurd. */
const MAX_CORRECTION = 3;

export class EstimateCalibration {
  private estimatedSeconds = 0;
  private realSeconds = 0;

  /** A render estimated at `estimatedSeconds` (before any correction) that took `realMs`. */
  record(estimatedSeconds: number, realMs: number): void {
    if (estimatedSeconds < MIN_ESTIMATED_SECONDS) return;
    this.estimatedSeconds += estimatedSeconds;
    this.realSeconds += realMs / 1000;
  }

  /** Real time per estimated time over the renders recorded and the prior minute, the longest weighing most; 1 before any. */
  get correction(): number {
    const ratio = (PRIOR_SECONDS + this.realSeconds) / (PRIOR_SECONDS + this.estimatedSeconds);
    return Math.min(MAX_CORRECTION, Math.max(1 / MAX_CORRECTION, ratio));
  }
}
