/**
 * What this session's renders have shown of this machine beyond the tiles' own time: wall
 * time per worker millisecond of tile work. A render takes longer than its tiles' work
 * shared by the workers: each tile is a message each way, the last tiles of a pass leave a
 * worker idle, and in the browser the page paints on the same cores. The time estimate
 * (measured-estimate.ts) multiplies by it.
 */
import type { FinishedRender } from './render-job.ts';

/**
 * Only renders with at least this much tile work per worker count: a short render's fixed
 * costs (the first message, the raster picture's read-back) say nothing of a long one's pace.
 */
const MIN_WORK_MS_PER_WORKER = 1000;

/** Never below 1 (a render is no faster than its work), never above this (a render stalled by something else, e.g. a laptop's sleep). */
const MAX_OVERHEAD = 3;

export class RenderSpeed {
  private wallMs = 0;
  private workMsPerWorker = 0;

  /** A finished render; its scene build is left out, as the probe before a render has built the scene. */
  record({ ms, sceneMs, workMs, workers }: FinishedRender): void {
    const perWorker = workMs / Math.max(1, workers);
    if (perWorker < MIN_WORK_MS_PER_WORKER) return;
    this.wallMs += ms - sceneMs;
    this.workMsPerWorker += perWorker;
  }

  /** Wall ms per worker ms over the renders recorded, the longest weighing most; 1 before any. */
  get overhead(): number {
    if (this.workMsPerWorker === 0) return 1;
    return Math.min(MAX_OVERHEAD, Math.max(1, this.wallMs / this.workMsPerWorker));
  }
}
