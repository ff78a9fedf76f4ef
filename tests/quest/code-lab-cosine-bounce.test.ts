import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { COSINE_BOUNCE_SIGNIFICANCE, cosineBounceRuns, drawCosineBounceFailure, tracerCosineDirection } from '../../src/quest/code-labs/cosine-bounce-lab.ts';
import { COSINE_NORMALS } from '../../src/quest/code-labs/cosine-bounce-normals.ts';
import { directionTally, gradeDirections } from '../../src/quest/code-labs/direction-statistics.ts';
import { runCases } from '../support/code-lab-run.ts';

type CosineDirection = (normal: Vec3, random: () => number) => unknown;

const SAMPLES = 1000;

function grade(cosineDirection: CosineDirection, seed = 23) {
  const runs = cosineBounceRuns(COSINE_NORMALS, SAMPLES, seed);
  const report = gradeDirections(
    runs,
    runCases(
      cosineDirection,
      runs.map((run) => run.args),
    ),
    COSINE_BOUNCE_SIGNIFICANCE,
  );
  return { runs, report };
}

const vec = (x: number, y: number, z: number): Vec3 => ({ x, y, z });
const add = (a: Vec3, b: Vec3) => vec(a.x + b.x, a.y + b.y, a.z + b.z);
const scale = (a: Vec3, s: number) => vec(a.x * s, a.y * s, a.z * s);
const cross = (a: Vec3, b: Vec3) => vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
const normalize = (a: Vec3) => scale(a, 1 / Math.hypot(a.x, a.y, a.z));

/** The frame a learner builds with the vector library: a helper axis not along n, crossed with n twice. */
function inFrame(n: Vec3, x: number, y: number, z: number): Vec3 {
  const helper = Math.abs(n.x) > 0.9 ? vec(0, 1, 0) : vec(1, 0, 0);
  const t = normalize(cross(helper, n));
  const b = cross(n, t);
  return add(add(scale(t, x), scale(b, y)), scale(n, z));
}

/** A point of the disc of radius r at angle φ, lifted to the hemisphere with height `height(r)`, in the frame of n. */
const lifted =
  (radius: (u: number) => number, height: (r: number) => number, turn = 2 * Math.PI, frame = inFrame): CosineDirection =>
  (n, random) => {
    const r = radius(random());
    const phi = turn * random();
    return frame(n, r * Math.cos(phi), r * Math.sin(phi), height(r));
  };

/** Malley's method with a polar map of the disc (pbrt-v4 §A.5.3; Shirley & Marschner §14.4). */
const malley = lifted(Math.sqrt, (r) => Math.sqrt(Math.max(0, 1 - r * r)));

/** The inverse of the CDF of cos θ, which is cos²θ: cos θ = √u. */
const inverseCdf: CosineDirection = (n, random) => {
  const cosTheta = Math.sqrt(random());
  const sinTheta = Math.sqrt(1 - cosTheta * cosTheta);
  const phi = 2 * Math.PI * random();
  return inFrame(n, sinTheta * Math.cos(phi), sinTheta * Math.sin(phi), cosTheta);
};

/** A uniform point of the unit sphere. */
function onSphere(random: () => number): Vec3 {
  const z = 2 * random() - 1;
  const r = Math.sqrt(1 - z * z);
  const phi = 2 * Math.PI * random();
  return vec(r * Math.cos(phi), r * Math.sin(phi), z);
}

/** The normal plus a uniform point of the unit sphere, normalized: cosine-weighted too (Shirley, "Ray Tracing in One Weekend", §8.3). */
const normalPlusSphere: CosineDirection = (n, random) => normalize(add(n, onSphere(random)));

describe('the cosine-weighted bounce lab', () => {
  it('passes the tracer’s own bounce and three other correct functions with any of 50 seeds', () => {
    for (let seed = 0; seed < 50; seed++) {
      for (const cosineDirection of [tracerCosineDirection, malley, inverseCdf, normalPlusSphere]) {
        const { report } = grade(cosineDirection, seed);
        expect(report.firstFailure, `seed ${seed}`).toBeNull();
        expect(Math.min(...report.tests.map((test) => test.p))).toBeGreaterThanOrEqual(report.significance);
        expect(directionTally(report, COSINE_NORMALS.length)).toEqual({ passed: 4004 + 8, total: 4004 + 8, failed: null });
      }
    }
  });

  it.each([
    [
      'uniform directions in the hemisphere',
      lifted(
        (u) => Math.sqrt(1 - (1 - u) ** 2),
        (r) => Math.sqrt(1 - r * r),
      ),
      'uneven-cos-theta',
    ],
    ['uniform directions in the whole sphere', (_n: Vec3, random: () => number) => onSphere(random), 'below-surface'],
    [
      'no frame around the normal (right only for +z)',
      lifted(
        Math.sqrt,
        (r) => Math.sqrt(1 - r * r),
        2 * Math.PI,
        (_n, x, y, z) => vec(x, y, z),
      ),
      'below-surface',
    ],
    [
      'the √ missing in Malley’s radius',
      lifted(
        (u) => u,
        (r) => Math.sqrt(1 - r * r),
      ),
      'uneven-cos-theta',
    ],
    ['the √ missing in Malley’s height', lifted(Math.sqrt, (r) => 1 - r * r), 'not-unit'],
    ['the normal plus a point of the sphere, not normalized', (n: Vec3, random: () => number) => add(n, onSphere(random)), 'not-unit'],
    ['φ over half a turn', lifted(Math.sqrt, (r) => Math.sqrt(1 - r * r), Math.PI), 'uneven-phi'],
    ['Math.random instead of the given random', (n: Vec3) => malley(n, Math.random), 'not-seeded'],
    ['nothing returned', () => undefined, 'not-a-vector'],
  ])('fails a function with %s on its named check', (_name, cosineDirection, check) => {
    for (const seed of [1, 23, 99]) {
      const { report } = grade(cosineDirection as CosineDirection, seed);
      expect(report.firstFailure?.check).toBe(check);
      const tally = directionTally(report, COSINE_NORMALS.length);
      expect(tally.passed).toBeLessThan(tally.total);
      expect(tally.failed).toBe(check);
    }
  });

  it('names the normal a function fails on: no frame is right on +z and wrong on −z', () => {
    const noFrame = lifted(
      Math.sqrt,
      (r) => Math.sqrt(1 - r * r),
      2 * Math.PI,
      (_n, x, y, z) => vec(x, y, z),
    );
    const { runs, report } = grade(noFrame);
    const failure = report.firstFailure!;
    expect(failure.check).toBe('below-surface');
    expect('run' in failure && runs[failure.run]!.kind).toBe('normal-minus-z');
    expect(report.passedRuns).toBeGreaterThanOrEqual(SAMPLES);
  });

  it('repeats each normal’s first seed once, and runs every normal with seeds of its own', () => {
    const runs = cosineBounceRuns(COSINE_NORMALS, SAMPLES, 5);
    expect(runs).toHaveLength(4 * SAMPLES + 4);
    const seeds = new Set(runs.filter((run) => run.repeats === undefined).map((run) => run.args[1].seededRandom));
    expect(seeds.size).toBe(4 * SAMPLES);
    for (const [group, repeat] of runs.slice(4 * SAMPLES).entries()) {
      expect(repeat.repeats).toBe(group * SAMPLES);
      expect(repeat.args).toEqual(runs[group * SAMPLES]!.args);
    }
  });

  it('draws the failing normal upright with its cosine lobe, the tracer’s directions and the learner’s', () => {
    const wholeSphere = (_n: Vec3, random: () => number) => onSphere(random);
    const noFrame = lifted(
      Math.sqrt,
      (r) => Math.sqrt(1 - r * r),
      2 * Math.PI,
      (_n, x, y, z) => vec(x, y, z),
    );
    for (const wrong of [wholeSphere, noFrame]) {
      const { runs, report } = grade(wrong);
      const drawing = drawCosineBounceFailure(report, runs)!;
      expect(drawing.cloud).toBe(true);
      expect(drawing.shapes).toEqual([{ kind: 'sphere', center: { x: 0, y: 0.5, z: 0 }, radius: 0.5 }]);
      expect(drawing.segments[0]).toMatchObject({ from: { x: 0, y: 0, z: 0 }, to: { x: 0, y: 1.3, z: 0 }, mark: 'normal' });
      const expected = drawing.points.filter((point) => point.mark === 'expected');
      const got = drawing.points.filter((point) => point.mark === 'got');
      expect(expected.length).toBeGreaterThan(0);
      expect(expected.every((point) => point.at.y >= 0 && Math.abs(Math.hypot(point.at.x, point.at.y, point.at.z) - 1) < 1e-9)).toBe(true);
      // Turned with their normal, the learner's directions keep their angle to it: many lie below the surface.
      expect(got.filter((point) => point.at.y < 0).length).toBeGreaterThan(got.length / 4);
      expect(drawing.segments.some((segment) => segment.mark === 'got' && segment.to.y < 0)).toBe(true);
    }
    expect(drawCosineBounceFailure(grade(malley).report, grade(malley).runs)).toBeNull();
  });
});
