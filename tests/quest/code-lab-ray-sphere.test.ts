import { describe, expect, it } from 'vitest';
import { gradeLab, type LabCase, type LabOutcome, type Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { RAY_SPHERE_EDGES } from '../../src/quest/code-labs/ray-sphere-edges.ts';
import { RAY_SPHERE_TOLERANCE, raySphereCases, tracerHitSphere } from '../../src/quest/code-labs/ray-sphere-lab.ts';

type HitSphere = (origin: Vec3, direction: Vec3, center: Vec3, radius: number) => unknown;

const dot = (a: Vec3, b: Vec3) => a.x * b.x + a.y * b.y + a.z * b.z;
const sub = (a: Vec3, b: Vec3): Vec3 => ({ x: a.x - b.x, y: a.y - b.y, z: a.z - b.z });

/** Runs a function on every case here, as the sandbox does in the browser. */
function outcomes(cases: LabCase[], hitSphere: HitSphere): LabOutcome[] {
  return cases.map((labCase) => {
    try {
      return { returned: hitSphere(...(labCase.args as [Vec3, Vec3, Vec3, number])) };
    } catch (error) {
      return { threw: String(error), line: null };
    }
  });
}

function grade(hitSphere: HitSphere, seed = 43) {
  const cases = raySphereCases(RAY_SPHERE_EDGES, 300, seed);
  return gradeLab(cases, outcomes(cases, hitSphere), RAY_SPHERE_TOLERANCE);
}

/** The textbook's form (Ray Tracing in One Weekend §5): a = d·d, b = 2·d·(o−c), c = |o−c|² − r². */
function fullForm(wrong: { discriminantSign?: boolean; acceptNegative?: boolean; noInside?: boolean; tangentMisses?: boolean } = {}): HitSphere {
  return (origin, direction, center, radius) => {
    const oc = sub(origin, center);
    const a = dot(direction, direction);
    const b = 2 * dot(direction, oc);
    const c = dot(oc, oc) - radius * radius;
    const disc = b * b - 4 * a * c;
    if (wrong.discriminantSign ? disc > 0 : wrong.tangentMisses ? disc <= 0 : disc < 0) return null;
    const near = (-b - Math.sqrt(disc)) / (2 * a);
    const far = (-b + Math.sqrt(disc)) / (2 * a);
    if (wrong.acceptNegative) return near;
    if (near > 0) return near;
    if (wrong.noInside) return null;
    return far > 0 ? far : null;
  };
}

describe('the ray–sphere lab', () => {
  it('passes a correct function in the textbook form, with any seed', () => {
    for (const seed of [1, 2, 43, 1000, 123456]) {
      const report = grade(fullForm(), seed);
      expect(report.firstFailure).toBeNull();
      expect(report.passed).toBe(report.total);
    }
  });

  it('has random cases that hit, miss and start inside', () => {
    const random = raySphereCases([], 300, 7);
    const hits = random.filter((labCase) => labCase.expected !== null).length;
    expect(hits).toBeGreaterThan(60);
    expect(random.length - hits).toBeGreaterThan(60);
  });

  it('agrees with the tracer on its named cases', () => {
    expect(tracerHitSphere({ x: 0, y: 0, z: -5 }, { x: 0, y: 0, z: 1 }, { x: 0, y: 0, z: 0 }, 1)).toBeCloseTo(4, 12);
    expect(tracerHitSphere({ x: 0, y: 0, z: 0.5 }, { x: 0, y: 0, z: 1 }, { x: 0, y: 0, z: 0 }, 2)).toBeCloseTo(1.5, 12);
    expect(tracerHitSphere({ x: 0, y: 0, z: 5 }, { x: 0, y: 0, z: 1 }, { x: 0, y: 0, z: 0 }, 1)).toBeNull();
  });

  it.each([
    ['the discriminant’s sign wrong', fullForm({ discriminantSign: true }), 'hit-from-outside', 'expected-hit'],
    ['t < 0 accepted', fullForm({ acceptNegative: true }), 'sphere-behind', 'expected-miss'],
    ['no hit from inside the sphere', fullForm({ noInside: true }), 'inside-sphere', 'expected-hit'],
    ['a tangent ray missed', fullForm({ tangentMisses: true }), 'tangent', 'expected-hit'],
  ])('fails a function with %s on its named case', (_name, hitSphere, kind, reason) => {
    const report = grade(hitSphere);
    expect(report.firstFailure?.labCase.kind).toBe(kind);
    expect(report.firstFailure?.reason).toBe(reason);
    expect(report.passed).toBeLessThan(report.total);
  });

  it('fails a function that forgets the centre on the off-centre case, with what it got', () => {
    const report = grade((origin, direction, _center, radius) => fullForm()(origin, direction, { x: 0, y: 0, z: 0 }, radius));
    expect(report.firstFailure).toMatchObject({ reason: 'expected-hit', got: null });
    expect(report.firstFailure?.labCase.kind).toBe('off-centre');
  });

  it('spells out NaN, a wrong type and an exception as failures of their case', () => {
    expect(grade(() => NaN).firstFailure).toMatchObject({ index: 0, reason: 'not-a-number', got: NaN });
    expect(grade(() => '4').firstFailure).toMatchObject({ index: 0, reason: 'wrong-type', got: '4' });
    expect(grade(() => undefined).firstFailure).toMatchObject({ reason: 'wrong-type', got: undefined });
    const cases = raySphereCases(RAY_SPHERE_EDGES, 0, 1);
    const report = gradeLab(cases, [{ returned: 4 }, { threw: 'ReferenceError: dott is not defined', line: 3 }], RAY_SPHERE_TOLERANCE);
    expect(report.firstFailure).toMatchObject({ index: 1, reason: 'threw', line: 3, message: 'ReferenceError: dott is not defined' });
  });

  it('fails a t off by more than the tolerance and passes one within it', () => {
    const off = (by: number) => (o: Vec3, d: Vec3, c: Vec3, r: number) => {
      const t = fullForm()(o, d, c, r);
      return typeof t === 'number' ? t * (1 + by) : t;
    };
    expect(grade(off(1e-4)).firstFailure?.reason).toBe('wrong-value');
    expect(grade(off(1e-8)).firstFailure).toBeNull();
  });

  it('counts passes per kind of case', () => {
    const report = grade(fullForm({ acceptNegative: true }));
    expect(report.kinds.find((kind) => kind.kind === 'sphere-behind')).toEqual({ kind: 'sphere-behind', passed: 0, total: 1 });
    expect(report.kinds.find((kind) => kind.kind === 'hit-from-outside')).toEqual({ kind: 'hit-from-outside', passed: 1, total: 1 });
  });
});
