import { Vector3 } from 'three';
import { perpendicularBasis } from '../../tracer/glossy.ts';
import { chiSquare, type ChiSquare } from './chi-square.ts';
import type { LabOutcome, Vec3 } from './code-lab-grading.ts';
import { dot } from './lab-vectors.ts';

/**
 * Grading a function that returns random directions around a normal with density cos θ / π
 * (spec/code-labs.md §2, as Nori's warping tests grade a sampling function). One direction
 * cannot be compared with the tracer's, so the function is run many times, each with a
 * seeded `random()`; every answer must be a unit vector in the hemisphere of its normal, a
 * run repeated with the same seed must give the same direction, and per normal the
 * directions' cos θ and their angle φ around the normal must follow the intended density:
 * χ² tests of both against it. A correct function fails them together by chance at most
 * once in 1/significance seeds: each of the tests gets an equal share (Bonferroni).
 */

/** One run: the normal's name (the kind of case), the arguments (the normal and { seededRandom: seed }), which run it repeats, if any. */
export interface DirectionRun {
  kind: string;
  args: [normal: Vec3, random: { seededRandom: number }];
  /** The index of the run with the same seed, whose direction this one must equal. */
  repeats?: number;
}

/** The two numbers the χ² tests look at: cos θ from the normal, and φ around it. */
export type DirectionMeasure = 'cos-theta' | 'phi';

export interface DirectionTest extends ChiSquare {
  normal: string;
  measure: DirectionMeasure;
  bins: number;
}

/** The first thing that failed, as data: the panel spells it out in the learner's language. */
export type DirectionFailure =
  | { check: 'threw'; run: number; message: string; line: number | null }
  | { check: 'not-a-vector'; run: number; got: unknown }
  | { check: 'not-unit'; run: number; direction: Vec3; length: number }
  | { check: 'below-surface'; run: number; direction: Vec3; cosTheta: number }
  | { check: 'not-seeded'; run: number; repeats: number }
  | { check: 'uneven-cos-theta' | 'uneven-phi'; test: DirectionTest };

export interface DirectionReport {
  runs: number;
  passedRuns: number;
  /** The learner's direction of each run, null where it was no vector. */
  directions: (Vec3 | null)[];
  /** The χ² tests, two per normal; empty when a run failed before they could be made. */
  tests: DirectionTest[];
  /** The significance each test is held to: the lab's, shared among the tests. */
  significance: number;
  firstFailure: DirectionFailure | null;
}

/** How far from 1 a unit direction's length may be: far above any way of computing it, far below anything a picture shows. */
export const UNIT_LENGTH_TOLERANCE = 1e-9;
/** A direction along the surface (cos θ = 0) has density 0, but rounding may put it a hair below. */
const SURFACE_TOLERANCE = 1e-9;
const COS_THETA_BINS = 10;
const PHI_BINS = 8;

export const isFiniteVector = (value: unknown): value is Vec3 =>
  typeof value === 'object' &&
  value !== null &&
  ['x', 'y', 'z'].every((key) => typeof (value as Record<string, unknown>)[key] === 'number' && Number.isFinite((value as Record<string, number>)[key]));

/** The checks of one run: a vector of finite numbers, of length 1, on the normal's side of the surface. */
function checkRun(value: unknown, normal: Vec3, run: number): DirectionFailure | null {
  if (!isFiniteVector(value)) return { check: 'not-a-vector', run, got: value };
  const direction = { x: value.x, y: value.y, z: value.z };
  const length = Math.hypot(direction.x, direction.y, direction.z);
  if (Math.abs(length - 1) > UNIT_LENGTH_TOLERANCE) return { check: 'not-unit', run, direction, length };
  const cosTheta = dot(direction, normal);
  if (cosTheta < -SURFACE_TOLERANCE) return { check: 'below-surface', run, direction, cosTheta };
  return null;
}

/**
 * The whole run graded: every run checked in order (the first failure kept), then, when all
 * passed, per normal the χ² tests of cos θ and φ; the first test below its share of the
 * significance is the failure.
 */
export function gradeDirections(runs: readonly DirectionRun[], outcomes: readonly LabOutcome[], significance: number): DirectionReport {
  const directions: (Vec3 | null)[] = [];
  let firstFailure: DirectionFailure | null = null;
  let passedRuns = 0;
  runs.forEach((directionRun, run) => {
    const outcome = outcomes[run] ?? { threw: 'no answer', line: null };
    const failure: DirectionFailure | null =
      'threw' in outcome
        ? { check: 'threw', run, message: outcome.threw, line: outcome.line }
        : (checkRun(outcome.returned, directionRun.args[0], run) ?? sameAsRepeated(directionRun, outcome.returned as Vec3, directions, run));
    directions.push('returned' in outcome && isFiniteVector(outcome.returned) ? outcome.returned : null);
    if (failure) firstFailure ??= failure;
    else passedRuns++;
  });
  const normals = [...new Set(runs.map((run) => run.kind))];
  const share = significance / (2 * normals.length);
  if (firstFailure) return { runs: runs.length, passedRuns, directions, tests: [], significance: share, firstFailure };
  const tests = normals.flatMap((normal) => {
    const group = runs.flatMap((run, index) =>
      run.kind === normal && run.repeats === undefined ? [{ normal: run.args[0], direction: directions[index]! }] : [],
    );
    return densityTests(normal, group);
  });
  const failed = tests.find((test) => test.p < share);
  return {
    runs: runs.length,
    passedRuns,
    directions,
    tests,
    significance: share,
    firstFailure: failed ? { check: failed.measure === 'cos-theta' ? 'uneven-cos-theta' : 'uneven-phi', test: failed } : null,
  };
}

/** A run that repeats an earlier seed must give the same direction: the function uses the random it is given, not Math.random. */
function sameAsRepeated(run: DirectionRun, direction: Vec3, directions: (Vec3 | null)[], index: number): DirectionFailure | null {
  if (run.repeats === undefined) return null;
  const earlier = directions[run.repeats];
  const same = earlier && earlier.x === direction.x && earlier.y === direction.y && earlier.z === direction.z;
  return same ? null : { check: 'not-seeded', run: index, repeats: run.repeats };
}

const reusable = { n: new Vector3(), t: new Vector3(), b: new Vector3() };

/**
 * The χ² tests of one normal's directions. With density cos θ / π per steradian, the chance
 * that cos θ ≤ c is ∫ 2 cos θ sin θ dθ from arccos c to π/2 = c²: cos²θ is uniform on [0, 1],
 * so bins of cos²θ of equal width are bins of equal chance; φ, the angle around the normal in
 * any frame perpendicular to it, is uniform on [0, 2π).
 */
function densityTests(normal: string, group: { normal: Vec3; direction: Vec3 }[]): DirectionTest[] {
  const cosThetaCounts = new Array<number>(COS_THETA_BINS).fill(0);
  const phiCounts = new Array<number>(PHI_BINS).fill(0);
  for (const { normal: n, direction: d } of group) {
    const { t, b } = reusable;
    perpendicularBasis(reusable.n.set(n.x, n.y, n.z), t, b);
    const cosTheta = Math.min(1, Math.max(0, dot(d, n)));
    cosThetaCounts[Math.min(COS_THETA_BINS - 1, Math.floor(cosTheta * cosTheta * COS_THETA_BINS))]!++;
    const phi = Math.atan2(d.x * b.x + d.y * b.y + d.z * b.z, d.x * t.x + d.y * t.y + d.z * t.z);
    const turn = phi / (2 * Math.PI) + (phi < 0 ? 1 : 0);
    phiCounts[Math.min(PHI_BINS - 1, Math.floor(turn * PHI_BINS))]!++;
  }
  const even = (bins: number) => new Array<number>(bins).fill(group.length / bins);
  return [
    { normal, measure: 'cos-theta', bins: COS_THETA_BINS, ...chiSquare(cosThetaCounts, even(COS_THETA_BINS)) },
    { normal, measure: 'phi', bins: PHI_BINS, ...chiSquare(phiCounts, even(PHI_BINS)) },
  ];
}

/** The report as the lab counts a run (code.graded): each run one case, each χ² test one more; `failed` the first failed check. */
export function directionTally(report: DirectionReport, normals: number): { passed: number; total: number; failed: string | null } {
  const testsPassed = report.tests.filter((test) => test.p >= report.significance).length;
  return { passed: report.passedRuns + testsPassed, total: report.runs + 2 * normals, failed: report.firstFailure?.check ?? null };
}
