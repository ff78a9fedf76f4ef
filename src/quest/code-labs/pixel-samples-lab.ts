import { hashKey } from '../../tracer/sampler.ts';
import { samplePosition } from '../../tracer/supersampling.ts';
import type { Point, RandomRun } from './code-lab-statistics.ts';

/**
 * The jittered samples lab (Cook, "Stochastic Sampling in Computer Graphics", ACM TOG 1986;
 * Shirley & Marschner, "Fundamentals of Computer Graphics", 4th ed., §13.4.1; pbrt-v4 §8.5).
 * The learner writes `pixelSamples(n, random)`: n points {x, y} in the pixel's unit square,
 * one at a uniform random place in each cell of a √n × √n grid, as the tracer's `jittered`
 * pattern puts its s × s samples (src/tracer/supersampling.ts). Graded statistically
 * (code-lab-statistics.ts).
 */

/** A correct function fails the χ² test by chance once in ten thousand seeds; every biased one the tests know fails it by far. */
export const PIXEL_SAMPLES_SIGNIFICANCE = 1e-4;

/**
 * The runs: `count` seeded runs, n taken in turn from `sizes`, each with a seed of its own
 * drawn from the level's; then run 0 once more with the same seed, whose points must be the same.
 */
export function pixelSampleRuns(sizes: readonly number[], count: number, seed: number): RandomRun[] {
  const runs: RandomRun[] = Array.from({ length: count }, (_, run) => ({
    kind: 'random',
    args: [sizes[run % sizes.length]!, { seededRandom: hashKey(seed, run) }],
  }));
  return [...runs, { kind: 'same-seed', args: runs[0]!.args, repeats: 0 }];
}

/**
 * The tracer's own jittered pattern as a function of the lab's shape: its s × s positions for
 * one pixel, with the seed of the tracer's hash drawn from the given `random`.
 */
export function tracerPixelSamples(n: number, random: () => number): Point[] {
  const cells = Math.round(Math.sqrt(n));
  const seed = Math.floor(random() * 2 ** 32);
  const out: [number, number] = [0, 0];
  return Array.from({ length: n }, (_, index) => {
    const [x, y] = samplePosition('jittered', cells, index, 0, 0, seed, out);
    return { x, y };
  });
}
