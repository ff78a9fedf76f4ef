import { describe, expect, it } from 'vitest';
import { gradeLab, type LabCase, type LabOutcome, type Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { SHADOW_EDGES } from '../../src/quest/code-labs/shadow-edges.ts';
import { drawShadowCase, SHADOW_TOLERANCE, shadowCases, tracerInShadow, type Sphere } from '../../src/quest/code-labs/shadow-lab.ts';

type InShadow = (point: Vec3, toLight: Vec3, distanceToLight: number, spheres: Sphere[]) => unknown;

/** Runs a function on every case here, as the sandbox does in the browser. */
function outcomes(cases: LabCase[], inShadow: InShadow): LabOutcome[] {
  return cases.map((labCase) => {
    try {
      return { returned: inShadow(...(structuredClone(labCase.args) as [Vec3, Vec3, number, Sphere[]])) };
    } catch (error) {
      return { threw: String(error), line: null };
    }
  });
}

function grade(inShadow: InShadow, seed = 4) {
  const cases = shadowCases(SHADOW_EDGES, 300, seed);
  return gradeLab(cases, outcomes(cases, inShadow), SHADOW_TOLERANCE);
}

/** The textbook shadow test (Shirley & Marschner §4.7) on the ray–sphere quadratic, and the ways learners get it wrong. */
function shadowTest(wrong: { ignoreDistance?: boolean; acceptNegative?: boolean; firstSphereOnly?: boolean } = {}): InShadow {
  return (p, d, distance, spheres) => {
    for (const { center, radius } of spheres) {
      const oc = { x: p.x - center.x, y: p.y - center.y, z: p.z - center.z };
      const b = oc.x * d.x + oc.y * d.y + oc.z * d.z;
      const disc = b * b - (oc.x * oc.x + oc.y * oc.y + oc.z * oc.z - radius * radius);
      const roots = disc < 0 ? [] : [-b - Math.sqrt(disc), -b + Math.sqrt(disc)];
      const blocks = roots.some((t) => (wrong.acceptNegative || t > 0) && (wrong.ignoreDistance || t < distance));
      if (blocks) return true;
      if (wrong.firstSphereOnly) return false;
    }
    return false;
  };
}

describe('the shadow-test lab', () => {
  it('passes a correct function, with any seed', () => {
    for (const seed of [1, 2, 4, 1000, 123456]) {
      const report = grade(shadowTest(), seed);
      expect(report.firstFailure).toBeNull();
      expect(report.passed).toBe(report.total);
    }
  });

  it('has random cases in shadow and in the light, with spheres behind the point and beyond the light', () => {
    const random = shadowCases([], 300, 7);
    const shadowed = random.filter((labCase) => labCase.expected === true).length;
    expect(shadowed).toBeGreaterThan(60);
    expect(random.length - shadowed).toBeGreaterThan(60);
    // The misconceptions matter in the random cases too: each wrong test fails on some of them.
    for (const wrong of [shadowTest({ ignoreDistance: true }), shadowTest({ acceptNegative: true })]) {
      expect(gradeLab(random, outcomes(random, wrong), SHADOW_TOLERANCE).passed).toBeLessThan(random.length - 10);
    }
  });

  it('answers its named cases as the tracer’s occlusion rule does', () => {
    const expected = Object.fromEntries(shadowCases(SHADOW_EDGES, 0, 1).map((labCase) => [labCase.kind, labCase.expected]));
    expect(expected).toEqual({
      blocked: true,
      'nothing-in-the-way': false,
      'beyond-the-light': false,
      'behind-the-point': false,
      'own-sphere': false,
      'several-spheres': true,
    });
    // The reach is the light's distance: the same sphere 1.5 m up blocks a light 2 m away, not one 1 m away.
    const up = { x: 0, y: 1, z: 0 };
    const sphere = { center: { x: 0, y: 2, z: 0 }, radius: 0.5 };
    expect(tracerInShadow({ x: 0, y: 0, z: 0 }, up, 2, [sphere])).toBe(true);
    expect(tracerInShadow({ x: 0, y: 0, z: 0 }, up, 1, [sphere])).toBe(false);
  });

  it.each([
    ['the light’s distance ignored', shadowTest({ ignoreDistance: true }), 'beyond-the-light'],
    ['hits at t < 0 counted', shadowTest({ acceptNegative: true }), 'behind-the-point'],
    ['only the first sphere looked at', shadowTest({ firstSphereOnly: true }), 'several-spheres'],
  ])('fails a function with %s on its named case', (_name, inShadow, kind) => {
    const report = grade(inShadow);
    expect(report.firstFailure?.labCase.kind).toBe(kind);
    expect(report.firstFailure?.reason).toBe('wrong-value');
    expect(report.passed).toBeLessThan(report.total);
  });

  it('fails a function that answers something other than true or false', () => {
    const report = grade(() => 1);
    expect(report.firstFailure).toMatchObject({ index: 0, reason: 'wrong-type' });
  });

  it('draws a failing case: the shadow ray, the spheres, the tracer’s blocking hit or the crossing a wrong "true" counted', () => {
    const [blocked, , , behind] = shadowCases(SHADOW_EDGES, 0, 1);
    const shadowDrawing = drawShadowCase(blocked!, null);
    expect(shadowDrawing.shapes).toHaveLength(1);
    expect(shadowDrawing.segments[0]).toMatchObject({ mark: 'ray', to: { x: 0, y: 4 + 1e-4, z: 0 } });
    expect(shadowDrawing.points).toEqual([{ at: { x: 0, y: 1.5, z: 0 }, mark: 'expected' }]);
    const report = grade(shadowTest({ acceptNegative: true }));
    const drawing = drawShadowCase(behind!, report.firstFailure);
    // The sphere below the point is crossed first at y = −1: t ≈ −1.0001, behind the point.
    expect(drawing.points).toHaveLength(1);
    expect(drawing.points[0]!.mark).toBe('got');
    expect(drawing.points[0]!.at.y).toBeCloseTo(-1, 9);
  });
});
