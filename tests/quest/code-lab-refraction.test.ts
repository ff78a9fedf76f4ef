import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { REFRACTION_EDGES } from '../../src/quest/code-labs/refraction-edges.ts';
import { REFRACTION_TOLERANCE, refractionCases, tracerRefract } from '../../src/quest/code-labs/refraction-lab.ts';
import { gradeFunction } from '../support/code-lab-grade.ts';

const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
const combine = (a: Vec3, s: number, b: Vec3, t: number): Vec3 => ({ x: s * a.x + t * b.x, y: s * a.y + t * b.y, z: s * a.z + t * b.z });

/** Snell's law in vector form (Shirley & Marschner §13.1), with each typical mistake as an option. */
function refractWith(wrong: { noTir?: 'nan' | 'clamped'; noFlip?: boolean; nothingInside?: boolean; etaInverted?: boolean } = {}) {
  return (d: Vec3, outward: Vec3, ior: number): Vec3 | null => {
    const inside = !wrong.nothingInside && dot(d, outward) > 0;
    const n = inside && !wrong.noFlip ? combine(outward, -1, outward, 0) : outward;
    let eta = inside ? ior : 1 / ior;
    if (wrong.etaInverted) eta = 1 / eta;
    const cosI = -dot(d, n);
    let k = 1 - eta * eta * (1 - cosI * cosI);
    if (wrong.noTir === 'clamped') k = Math.max(k, 0);
    else if (k < 0 && !wrong.noTir) return null;
    return combine(d, eta, n, eta * cosI - Math.sqrt(k));
  };
}
const grade = (refract: (d: Vec3, n: Vec3, ior: number) => unknown, seed = 6) =>
  gradeFunction(refractionCases(REFRACTION_EDGES, 300, seed), REFRACTION_TOLERANCE, refract);

describe('the refraction lab', () => {
  it('passes a correct function with any seed', () => {
    for (const seed of [1, 6, 43, 2024, 77777]) expect(grade(refractWith(), seed)).toMatchObject({ firstFailure: null, passed: 305 });
  });

  it('has random cases into and out of the glass, some totally reflected', () => {
    const random = refractionCases([], 300, 3);
    const inside = random.filter(({ args }) => dot(args[0] as Vec3, args[1] as Vec3) > 0);
    expect(inside.length).toBeGreaterThan(100);
    expect(random.length - inside.length).toBeGreaterThan(100);
    expect(inside.filter(({ expected }) => expected === null).length).toBeGreaterThan(30);
  });

  it('agrees with the tracer: 45° into glass bends to 28°, 60° inside glass stays inside', () => {
    const bent = tracerRefract({ x: Math.SQRT1_2, y: -Math.SQRT1_2, z: 0 }, { x: 0, y: 1, z: 0 }, 1.5)!;
    expect(Math.asin(bent.x)).toBeCloseTo(Math.asin(Math.SQRT1_2 / 1.5), 12);
    expect(bent.y).toBeLessThan(0);
    expect(tracerRefract({ x: Math.sin(Math.PI / 3), y: Math.cos(Math.PI / 3), z: 0 }, { x: 0, y: 1, z: 0 }, 1.5)).toBeNull();
  });

  it.each([
    ['no total internal reflection (a square root of a negative number)', refractWith({ noTir: 'nan' }), 'total-internal-reflection', 'not-a-number'],
    ['no total internal reflection (the root taken as 0)', refractWith({ noTir: 'clamped' }), 'total-internal-reflection', 'expected-miss'],
    ['the normal not flipped inside the glass', refractWith({ noFlip: true }), 'out-of-glass-slanted', 'wrong-value'],
    ['every ray treated as entering the glass', refractWith({ nothingInside: true }), 'out-of-glass-slanted', 'wrong-value'],
    ['η upside down (n instead of 1/n going in)', refractWith({ etaInverted: true }), 'into-glass-slanted', 'expected-hit'],
  ])('fails a function with %s on its named case', (_name, refract, kind, reason) => {
    const report = grade(refract);
    expect(report.firstFailure?.labCase.kind).toBe(kind);
    expect(report.firstFailure?.reason).toBe(reason);
  });
});
