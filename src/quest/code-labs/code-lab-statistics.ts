import { chiSquare, type ChiSquare } from './chi-square.ts';
import type { LabOutcome } from './code-lab-grading.ts';

/**
 * Grading a random function (spec/code-labs.md §2): its answers cannot be compared one by
 * one with the tracer's, so they are tested as a sample, as Nori's warping tests do. The
 * function gets a seeded `random()` (the sandbox makes it from the seed the page sends) and
 * is run many times; each run must give points that are inside the pixel and stratified
 * (one in each cell of a √n × √n grid), the same points for the same seed (it uses the
 * random it is given), and all runs together must spread evenly within their cells: a χ²
 * test of the points' places in their cells against the uniform density, at a stated
 * significance. A correct function passes with any seed, bar a chance of `significance`.
 */

/** One run: the arguments (n and { seededRandom: seed }), and which run it repeats, if any. */
export interface RandomRun {
  kind: string;
  args: [n: number, random: { seededRandom: number }];
  /** The index of the run with the same seed, whose points this one must equal. */
  repeats?: number;
}

export interface Point {
  x: number;
  y: number;
}

/**
 * The first thing that failed, as data: the panel spells it out in the learner's language.
 * A failure of a run whose answer was n points carries them (copies, plain data), so that the
 * 3D view can draw the run (pixel-samples-lab.ts); `uneven-within-cells` carries the points
 * of the run with the most of them, where their places within the cells show best.
 */
export type SampleFailure =
  | { check: 'threw'; run: number; message: string; line: number | null }
  | { check: 'not-points'; run: number; got: string }
  | { check: 'wrong-count'; run: number; got: number; wanted: number }
  | { check: 'outside-pixel'; run: number; point: Point; points: Point[] }
  | { check: 'two-in-a-cell'; run: number; cell: [column: number, row: number]; cells: number; points: Point[] }
  | { check: 'not-seeded'; run: number; repeats: number; points: Point[] }
  | { check: 'uneven-within-cells'; run: number; points: Point[] };

export interface StatisticsReport {
  runs: number;
  /** How many points all runs gave together, and how many runs passed the checks of one run. */
  points: number;
  passedRuns: number;
  /** The χ² of the points' places within their cells; null when a run failed before it could be made. */
  test: (ChiSquare & { significance: number; bins: number }) | null;
  firstFailure: SampleFailure | null;
}

/** What one run's answer is: n finite points, or why not (also how a render with the function reads one pixel's answer). */
export function pointsOf(value: unknown, n: number, run: number): Point[] | SampleFailure {
  if (!Array.isArray(value)) return { check: 'not-points', run, got: describeKind(value) };
  if (value.length !== n) return { check: 'wrong-count', run, got: value.length, wanted: n };
  for (const point of value) {
    const { x, y } = (point ?? {}) as Partial<Point>;
    if (typeof x !== 'number' || typeof y !== 'number' || !Number.isFinite(x) || !Number.isFinite(y)) {
      return { check: 'not-points', run, got: describeKind(point) };
    }
  }
  return (value as Point[]).map(({ x, y }) => ({ x, y }));
}

const describeKind = (value: unknown) => (value === null ? 'null' : Array.isArray(value) ? 'array' : typeof value);

/** The checks of one run: inside the pixel [0, 1)², then one point per cell of the √n × √n grid. */
function checkRun(points: Point[], run: number): SampleFailure | null {
  const cells = Math.round(Math.sqrt(points.length));
  const outside = points.find(({ x, y }) => !(x >= 0 && x < 1 && y >= 0 && y < 1));
  if (outside) return { check: 'outside-pixel', run, point: outside, points };
  const taken = new Set<number>();
  for (const { x, y } of points) {
    const cell = Math.floor(y * cells) * cells + Math.floor(x * cells);
    if (taken.has(cell)) return { check: 'two-in-a-cell', run, cell: [cell % cells, Math.floor(cell / cells)], cells, points };
    taken.add(cell);
  }
  return null;
}

/**
 * The whole run graded: every run checked in order (the first failure kept), then, when all
 * passed, the χ² of where the points lie within their cells (u, v = the point's place in its
 * cell, 0 to 1) over a grid of bins, against the same count in every bin.
 */
export function gradeSamples(runs: readonly RandomRun[], outcomes: readonly LabOutcome[], significance: number): StatisticsReport {
  const answers: Point[][] = [];
  let firstFailure: SampleFailure | null = null;
  let passedRuns = 0;
  runs.forEach((randomRun, run) => {
    const outcome = outcomes[run] ?? { threw: 'no answer', line: null };
    const points =
      'threw' in outcome ? { check: 'threw' as const, run, message: outcome.threw, line: outcome.line } : pointsOf(outcome.returned, randomRun.args[0], run);
    const failure = Array.isArray(points) ? (checkRun(points, run) ?? sameAsRepeated(randomRun, points, answers, run)) : points;
    answers.push(Array.isArray(points) ? points : []);
    if (failure) firstFailure ??= failure;
    else passedRuns++;
  });
  const points = answers.reduce((sum, list) => sum + list.length, 0);
  if (firstFailure) return { runs: runs.length, points, passedRuns, test: null, firstFailure };
  const test = withinCellTest(answers, significance);
  const largest = answers.reduce((best, list, run) => (list.length > answers[best]!.length ? run : best), 0);
  const uneven: SampleFailure = { check: 'uneven-within-cells', run: largest, points: answers[largest]! };
  return { runs: runs.length, points, passedRuns, test, firstFailure: test.p < significance ? uneven : null };
}

/** A run that repeats an earlier seed must give the same points: the function uses the random it is given, not Math.random. */
function sameAsRepeated(run: RandomRun, points: Point[], answers: Point[][], index: number): SampleFailure | null {
  if (run.repeats === undefined) return null;
  const earlier = answers[run.repeats] ?? [];
  const same = earlier.length === points.length && earlier.every((point, at) => point.x === points[at]!.x && point.y === points[at]!.y);
  return same ? null : { check: 'not-seeded', run: index, repeats: run.repeats, points };
}

/** χ² of the points' places within their cells over bins × bins bins; about 25 points a bin, 2 to 8 bins a side. */
function withinCellTest(answers: Point[][], significance: number): ChiSquare & { significance: number; bins: number } {
  const total = answers.reduce((sum, list) => sum + list.length, 0);
  const bins = Math.max(2, Math.min(8, Math.floor(Math.sqrt(total / 25))));
  const observed = new Array<number>(bins * bins).fill(0);
  for (const points of answers) {
    const cells = Math.round(Math.sqrt(points.length));
    for (const { x, y } of points) {
      const u = x * cells - Math.floor(x * cells);
      const v = y * cells - Math.floor(y * cells);
      observed[Math.min(bins - 1, Math.floor(v * bins)) * bins + Math.min(bins - 1, Math.floor(u * bins))]!++;
    }
  }
  const expected = observed.map(() => total / (bins * bins));
  return { ...chiSquare(observed, expected), significance, bins };
}

/** The report as the lab counts a run (code.graded): each run one case, the χ² test one more; `failed` the first failed check. */
export function sampleTally(report: StatisticsReport): { passed: number; total: number; failed: string | null } {
  const testPassed = report.test !== null && report.test.p >= report.test.significance;
  return { passed: report.passedRuns + (testPassed ? 1 : 0), total: report.runs + 1, failed: report.firstFailure?.check ?? null };
}
