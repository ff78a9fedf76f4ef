import { describe, expect, it } from 'vitest';
import { gradeLab, type LabCase, type LabOutcome, type Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { RAY_BOX_EDGES } from '../../src/quest/code-labs/ray-box-edges.ts';
import { RAY_BOX_TOLERANCE, rayBoxCases, tracerHitBox } from '../../src/quest/code-labs/ray-box-lab.ts';
import { slabTest, type HitBox } from '../support/slab-tests.ts';

const AXES = ['x', 'y', 'z'] as const;

/** Runs a function on every case here, as the sandbox does in the browser. */
function outcomes(cases: LabCase[], hitBox: HitBox): LabOutcome[] {
  return cases.map((labCase) => {
    try {
      return { returned: hitBox(...(labCase.args as [Vec3, Vec3, Vec3, Vec3])) };
    } catch (error) {
      return { threw: String(error), line: null };
    }
  });
}

function grade(hitBox: HitBox, seed = 15) {
  const cases = rayBoxCases(RAY_BOX_EDGES, 300, seed);
  return gradeLab(cases, outcomes(cases, hitBox), RAY_BOX_TOLERANCE);
}

describe('the AABB slab test lab', () => {
  it('passes a correct function in the textbook form, with any seed', () => {
    for (const seed of [1, 2, 15, 1000, 123456]) {
      const report = grade(slabTest(), seed);
      expect(report.firstFailure).toBeNull();
      expect(report.passed).toBe(report.total);
    }
  });

  it('has random cases that hit, miss and start inside', () => {
    const random = rayBoxCases([], 300, 7);
    const hits = random.filter((labCase) => labCase.expected !== null);
    expect(hits.length).toBeGreaterThan(60);
    expect(random.length - hits.length).toBeGreaterThan(60);
    const inside = random.filter(({ args }) => {
      const [o, , min, max] = args as Vec3[];
      return AXES.every((axis) => min![axis] < o![axis] && o![axis] < max![axis]);
    });
    expect(inside.length).toBeGreaterThan(20);
  });

  it('answers its named cases as the tracer’s box test does, ties included', () => {
    const expected = Object.fromEntries(rayBoxCases(RAY_BOX_EDGES, 0, 1).map((labCase) => [labCase.kind, labCase.expected]));
    // Along (3, 2, 6)/7 from (−3, −2, −6) the z slab is entered last, at z = −1: t = 7 · 5/6.
    expect(expected['box-hit-from-outside']).toBeCloseTo(35 / 6, 12);
    expect(expected['box-miss']).toBeNull();
    expect(expected['box-behind']).toBeNull();
    expect(expected['inside-box']).toBeGreaterThan(0);
    expect(expected['negative-direction']).toBeCloseTo((7 * 2) / 3, 12);
    expect(expected['parallel-inside-slab']).toBeCloseTo(3.75, 12);
    expect(expected['parallel-outside-slab']).toBeNull();
    // 0 · ∞ is NaN on the face's plane: the tracer counts the ray as a miss.
    expect(expected['in-face-plane']).toBeNull();
    // Entry and exit at the same t: touching counts, as t_near ≤ t_far.
    expect(expected['touches-edge']).toBeCloseTo(Math.sqrt(3), 12);
    // The scaled unit cube agrees with the textbook form on a box that is not a cube.
    expect(tracerHitBox({ x: -5, y: 0.5, z: 1 }, { x: 1, y: 0, z: 0 }, { x: -2, y: 0, z: 0 }, { x: 3, y: 1, z: 4 })).toBeCloseTo(3, 12);
  });

  it.each([
    ['parallel rays made to miss', slabTest({ parallelMisses: true }), 'parallel-inside-slab', 'expected-hit'],
    ['the parallel slab skipped', slabTest({ parallelIgnored: true }), 'parallel-outside-slab', 'expected-miss'],
    ['NaN from 0 · ∞ let through', slabTest({ nanThrough: true }), 'in-face-plane', 'not-a-number'],
    ['t < 0 accepted', slabTest({ acceptNegative: true }), 'box-behind', 'expected-miss'],
    ['no hit from inside the box', slabTest({ noInside: true }), 'inside-box', 'expected-hit'],
    ['entry and exit not swapped for a negative direction', slabTest({ noSwap: true }), 'negative-direction', 'expected-hit'],
    ['a ray touching an edge missed', slabTest({ touchMisses: true }), 'touches-edge', 'expected-hit'],
  ])('fails a function with %s on its named case', (_name, hitBox, kind, reason) => {
    const report = grade(hitBox);
    expect(report.firstFailure?.labCase.kind).toBe(kind);
    expect(report.firstFailure?.reason).toBe(reason);
    expect(report.passed).toBeLessThan(report.total);
  });

  it('fails a function that answers the exit instead of the entry on the first case, with what it got', () => {
    const exitOnly: HitBox = (o, d, min, max) => {
      if (slabTest()(o, d, min, max) === null) return null;
      return Math.min(...AXES.map((axis) => Math.max((min[axis] - o[axis]) / d[axis], (max[axis] - o[axis]) / d[axis])));
    };
    const report = grade(exitOnly);
    expect(report.firstFailure).toMatchObject({ index: 0, reason: 'wrong-value', gotValue: 7 * (7 / 6) });
    expect(report.firstFailure?.labCase.kind).toBe('box-hit-from-outside');
  });
});
