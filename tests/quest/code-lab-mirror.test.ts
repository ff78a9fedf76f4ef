import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { MIRROR_EDGES } from '../../src/quest/code-labs/mirror-edges.ts';
import { MIRROR_TOLERANCE, mirrorCases, tracerReflect } from '../../src/quest/code-labs/mirror-lab.ts';
import { gradeFunction } from '../support/code-lab-grade.ts';

const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
/** d − k·(d·n)·n: k = 2 is the mirror (Shirley & Marschner §4.8). */
const reflectWith = (k: number) => (d: Vec3, n: Vec3) => {
  const s = k * dot(d, n);
  return { x: d.x - s * n.x, y: d.y - s * n.y, z: d.z - s * n.z };
};
const grade = (reflect: (d: Vec3, n: Vec3) => unknown, seed = 5) => gradeFunction(mirrorCases(MIRROR_EDGES, 300, seed), MIRROR_TOLERANCE, reflect);

describe('the mirror lab', () => {
  it('passes a correct function with any seed', () => {
    for (const seed of [1, 5, 43, 9999]) expect(grade(reflectWith(2), seed)).toMatchObject({ firstFailure: null, passed: 304 });
  });

  it('agrees with the tracer: straight back, and up again at 45°', () => {
    expect(tracerReflect({ x: 0, y: 0, z: -1 }, { x: 0, y: 0, z: 1 })).toEqual({ x: 0, y: 0, z: 1 });
    const up = tracerReflect({ x: Math.SQRT1_2, y: -Math.SQRT1_2, z: 0 }, { x: 0, y: 1, z: 0 });
    expect(up.x).toBeCloseTo(Math.SQRT1_2, 15);
    expect(up.y).toBeCloseTo(Math.SQRT1_2, 15);
  });

  it.each([
    ['the normal term’s sign wrong', reflectWith(-2)],
    ['the dot product used once (a ray along the mirror)', reflectWith(1)],
  ])('fails a function with %s on the slanted case', (_name, reflect) => {
    const report = grade(reflect);
    expect(report.firstFailure).toMatchObject({ index: 0, reason: 'wrong-value' });
    expect(report.firstFailure?.labCase.kind).toBe('mirror-slanted');
  });

  it('fails a head-on ray that comes out as no direction at all', () => {
    const report = gradeFunction(mirrorCases(['mirror-head-on'], 0, 1), MIRROR_TOLERANCE, reflectWith(1));
    expect(report.firstFailure).toMatchObject({ reason: 'wrong-value', got: { x: 0, y: 0, z: 0 } });
  });

  it('fails a direction of the wrong length, and one right only for normals along an axis on the tilted case', () => {
    const twice = (d: Vec3, n: Vec3) => {
      const r = reflectWith(2)(d, n);
      return { x: 2 * r.x, y: 2 * r.y, z: 2 * r.z };
    };
    expect(grade(twice).firstFailure).toMatchObject({ index: 0, reason: 'not-unit' });
    // Right for floors and walls along the axes only: it flips the components the normal has.
    const flipAxes = (d: Vec3, n: Vec3) => ({ x: n.x ? -d.x : d.x, y: n.y ? -d.y : d.y, z: n.z ? -d.z : d.z });
    expect(grade(flipAxes).firstFailure?.labCase.kind).toBe('mirror-tilted');
  });
});
