/** How many worker threads `rt render` starts when --workers is not given. */
import { estimateRender } from '../render/render-estimate.ts';
import type { Scene } from '../scene/scene.ts';

/**
 * Without --workers, a render its one-worker estimate (render-estimate.ts) puts under this
 * many seconds gets one worker thread; a longer one gets one per core. Every thread starts
 * cold, whatever its share of the image: it boots, builds the scene's BVHs and runs its first
 * rays before V8 has optimized them. On a 2-core machine the command's main thread and two
 * workers then share the cores, and the second worker made a small render slower. Measured
 * there (the reference scene, whole command, 3 runs each, one thread against two): 16 × 16
 * 0.43-0.46 s against 0.51-0.55 s; 160 × 160 (estimate 1.5 s) 1.03-1.05 against 1.04-1.11 s;
 * 192 × 192 (2.1 s) 1.14-1.18 against 1.18-1.21 s; 224 × 224 (2.9 s) 1.38-1.45 against
 * 1.25-1.31 s; 256 × 256 (3.8 s) 1.62-1.68 against 1.45-1.50 s. With more cores the threads
 * share less, so the threshold is if anything lower there; it is not measured.
 */
export const SINGLE_WORKER_SECONDS = 2.5;

/** One worker for a render estimated under SINGLE_WORKER_SECONDS on one, else `cores`. */
export function workersWorthStarting(scene: Scene, width: number, height: number, cores: number): number {
  return estimateRender(scene, width, height, 1).seconds < SINGLE_WORKER_SECONDS ? 1 : cores;
}
