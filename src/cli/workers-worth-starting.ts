/** How many worker threads `rt render` starts when --workers is not given. */
import { estimateRender } from '../render/render-estimate.ts';
import type { Scene } from '../scene/scene.ts';

/**
 * Without --workers, a render its one-worker estimate (render-estimate.ts) puts under this
 * many seconds gets one worker thread; a longer one gets one per core. Every thread starts
 * cold, whatever its share of the image: it boots, builds the scene's BVHs and runs its first
 * rays before the engine has optimized them. On a 2-core machine the command's main thread
 * and two workers then share the cores, and a second worker made a small render slower; the
 * threshold is where two began to pay (docs/performance.md, "Cold code").
 */
export const SINGLE_WORKER_SECONDS = 2.5;

/** One worker for a render estimated under SINGLE_WORKER_SECONDS on one, else `cores`. */
export function workersWorthStarting(scene: Scene, width: number, height: number, cores: number): number {
  return estimateRender(scene, width, height, 1).seconds < SINGLE_WORKER_SECONDS ? 1 : cores;
}
