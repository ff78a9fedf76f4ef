import { Quaternion, Vector3 } from 'three';
import { sampleHemisphere } from '../../tracer/hemisphere-sampling.ts';
import { hashKey, RandomStream } from '../../tracer/sampler.ts';
import type { CaseDrawing } from './case-drawing.ts';
import type { CosineNormal } from './cosine-bounce-normals.ts';
import type { Vec3 } from './code-lab-grading.ts';
import type { DirectionReport, DirectionRun } from './direction-statistics.ts';
import { unit, v } from './lab-vectors.ts';

/**
 * The cosine-weighted bounce lab (path-tracing chapter, level 23): the learner writes
 * `cosineDirection(normal, random)`, a unit direction in the hemisphere around the normal
 * with density cos θ / π, as the tracer picks a diffuse bounce (src/tracer/hemisphere-sampling.ts:
 * Malley's method, pbrt-v4 §A.5.3). Its numbers need not be the tracer's (a polar map and the
 * concentric one give other directions for the same random numbers), only its density: graded
 * statistically (direction-statistics.ts).
 */

/** A correct function fails the χ² tests by chance at most once in ten thousand seeds; every wrong one the tests know fails by far. */
export const COSINE_BOUNCE_SIGNIFICANCE = 1e-4;

const NORMALS: Record<CosineNormal, Vec3> = {
  'normal-plus-z': v(0, 0, 1),
  'normal-minus-z': v(0, 0, -1),
  'normal-plus-y': v(0, 1, 0),
  'normal-slanted': unit(v(1, -2, 2)),
};

/**
 * The runs: `samples` seeded runs per normal, each with a seed of its own drawn from the
 * level's; then each normal's first run once more with the same seed, whose direction must be the same.
 */
export function cosineBounceRuns(normals: readonly CosineNormal[], samples: number, seed: number): DirectionRun[] {
  const runs: DirectionRun[] = normals.flatMap((name, group) =>
    Array.from({ length: samples }, (_, index): DirectionRun => ({ kind: name, args: [NORMALS[name], { seededRandom: hashKey(seed, group, index) }] })),
  );
  const repeats = normals.map((_, group): DirectionRun => ({ ...runs[group * samples]!, repeats: group * samples }));
  return [...runs, ...repeats];
}

const reusable = { n: new Vector3(), t: new Vector3(), b: new Vector3(), out: new Vector3() };

/** The tracer's own cosine bounce as a function of the lab's shape, its two numbers drawn from the given `random`. */
export function tracerCosineDirection(normal: Vec3, random: () => number): Vec3 {
  const { n, t, b, out } = reusable;
  const u = random();
  sampleHemisphere('cosine', n.set(normal.x, normal.y, normal.z), u, random(), t, b, out);
  return v(out.x, out.y, out.z);
}

/** How many directions of each kind the 3D view shows: enough to see where they crowd, few enough to see each. */
const SHOWN = 50;

/**
 * The failing normal drawn at the origin: the normal, the cosine lobe (cos θ as a polar plot,
 * the directions' density cos θ / π times π: a sphere of diameter 1 touching the surface at the origin),
 * the tips of the learner's directions (got) and the tracer's for the same seeds (expected):
 * where they crowd, and on which side of the surface they lie, shows what went wrong. The
 * failing run's own direction is drawn as an arrow. All of it is turned so that the normal
 * points up (+y): the level's camera looks along −z, and a normal along ±z seen end-on would
 * hide which side of the surface a direction lies on; turning keeps every angle to the normal.
 */
export function drawCosineBounceFailure(report: DirectionReport, runs: readonly DirectionRun[]): CaseDrawing | null {
  const failure = report.firstFailure;
  if (!failure) return null;
  const kind = 'run' in failure ? runs[failure.run]?.kind : failure.test.normal;
  const group = runs.flatMap((run, index) => (run.kind === kind && run.repeats === undefined ? [index] : []));
  const normal = runs[group[0] ?? 0]?.args[0];
  if (!normal) return null;
  const upright = new Quaternion().setFromUnitVectors(new Vector3(normal.x, normal.y, normal.z), new Vector3(0, 1, 0));
  const turned = (direction: Vec3): Vec3 => {
    const length = Math.hypot(direction.x, direction.y, direction.z);
    // A learner's vector drawn at most 2 long, so a wild one does not shrink the rest out of sight.
    const turnedVector = new Vector3(direction.x, direction.y, direction.z).multiplyScalar(length > 2 ? 2 / length : 1).applyQuaternion(upright);
    return v(turnedVector.x, turnedVector.y, turnedVector.z);
  };
  const origin = v(0, 0, 0);
  const drawing: CaseDrawing = {
    segments: [{ from: origin, to: v(0, 1.3, 0), mark: 'normal', arrow: true }],
    points: [],
    shapes: [{ kind: 'sphere', center: v(0, 0.5, 0), radius: 0.5 }],
    cloud: true,
  };
  for (const index of group.slice(0, SHOWN)) {
    const run = runs[index]!;
    // The tracer's generator, not the sandbox's: other numbers for the seed, the same density.
    const stream = new RandomStream().reset(run.args[1].seededRandom);
    drawing.points.push({ at: turned(tracerCosineDirection(normal, () => stream.next())), mark: 'expected' });
    const got = report.directions[index];
    if (got) drawing.points.push({ at: turned(got), mark: 'got' });
  }
  const failed = 'run' in failure ? report.directions[failure.run] : null;
  if (failed) drawing.segments.push({ from: origin, to: turned(failed), mark: 'got', arrow: true });
  return drawing;
}
