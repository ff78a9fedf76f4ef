/** How many worker threads `rt render` starts when --workers is not given. */
import { estimateRender } from '../render/render-estimate.ts';
import type { Scene } from '../scene/scene.ts';

/**
 * Without --workers, one worker thread per this many seconds of the render's one-worker
 * estimate (render-estimate.ts), at least one and at most one per core. Every thread starts
 * cold, whatever its share of the image: it boots, builds the scene's BVHs and runs its first
 * rays before V8 has optimized them, about 0.1-0.15 s of wall time on a 2-core machine. So
 * two threads made a small render slower: the reference scene (2 cores, Zen 3, wall time of
 * the whole command, 3 runs each) at 16 × 16 took 0.43-0.46 s on one and 0.51-0.55 s on two;
 * 128 × 128 (estimate 0.9 s) 0.81-0.84 s and 0.92-0.93 s; 192 × 192 (2.1 s) 1.18-1.21 s and
 * 1.14-1.20 s; 256 × 256 (3.8 s) 1.62-1.67 s and 1.49-1.52 s; 384 × 384 3.06-3.17 s and 2.10-2.20 s.
 */
export const ESTIMATED_SECONDS_PER_WORKER = 1.5;

/** One worker per ESTIMATED_SECONDS_PER_WORKER of the render's one-worker estimate, 1 to `cores`. */
export function workersWorthStarting(scene: Scene, width: number, height: number, cores: number): number {
  const seconds = estimateRender(scene, width, height, 1).seconds;
  return Math.max(1, Math.min(cores, Math.floor(seconds / ESTIMATED_SECONDS_PER_WORKER)));
}
