import { hashKey } from '../../tracer/sampler.ts';
import { samplePosition } from '../../tracer/supersampling.ts';
import type { CaseDrawing, CaseShape, CaseSegment, QuadFill } from './case-drawing.ts';
import type { Point, RandomRun, SampleFailure } from './code-lab-statistics.ts';
import { v } from './lab-vectors.ts';

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

/** A point far outside the pixel is drawn this far outside at most, so that the pixel stays large enough to read. */
const FARTHEST_OUTSIDE = 0.5;

const clampOutside = (value: number) => Math.min(1 + FARTHEST_OUTSIDE, Math.max(-FARTHEST_OUTSIDE, value));

/** The quad of the pixel's part from (x0, y0) to (x1, y1), in the plane z = 0 (1 m to the pixel). */
const quad = (x0: number, y0: number, x1: number, y1: number, fill: QuadFill): CaseShape => ({
  kind: 'quad',
  corners: [v(x0, y0, 0), v(x1, y0, 0), v(x1, y1, 0), v(x0, y1, 0)],
  fill,
});

/**
 * A failing run drawn in 3D: the pixel as a 1 m square in the plane z = 0 (x to the right, y
 * up), seen face on, with its √n × √n grid of cells; the run's points on it, each inside
 * the pixel a small dot and each outside it marked as the learner's wrong answer (◆, drawn
 * at most FARTHEST_OUTSIDE beyond the edge); the cells with no point and those with more
 * than one filled, so that points not stratified show at a glance. Null for a failure that
 * carries no points (the function threw or gave no n points).
 */
export function drawSampleRun(failure: SampleFailure): CaseDrawing | null {
  if (!('points' in failure)) return null;
  const points = failure.points;
  const cells = Math.max(1, Math.round(Math.sqrt(points.length)));
  const counts = new Array<number>(cells * cells).fill(0);
  const drawing: CaseDrawing = { segments: [], points: [], shapes: [quad(0, 0, 1, 1, 'pixel')], lookFrom: v(0, 0, 1) };
  for (const { x, y } of points) {
    const inside = x >= 0 && x < 1 && y >= 0 && y < 1;
    if (inside) counts[Math.floor(y * cells) * cells + Math.floor(x * cells)]!++;
    drawing.points.push({ at: v(clampOutside(x), clampOutside(y), 0), mark: inside ? 'sample' : 'got' });
  }
  counts.forEach((count, cell) => {
    if (count === 1) return;
    const [column, row] = [cell % cells, Math.floor(cell / cells)];
    drawing.shapes.push(quad(column / cells, row / cells, (column + 1) / cells, (row + 1) / cells, count === 0 ? 'empty' : 'crowded'));
  });
  for (let line = 1; line < cells; line++) {
    const at = line / cells;
    const grid: CaseSegment[] = [
      { from: v(at, 0, 0), to: v(at, 1, 0), mark: 'grid' },
      { from: v(0, at, 0), to: v(1, at, 0), mark: 'grid' },
    ];
    drawing.segments.push(...grid);
  }
  return drawing;
}
