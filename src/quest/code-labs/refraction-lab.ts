import { Vector3 } from 'three';
import { refract, relativeIndex } from '../../tracer/fresnel.ts';
import { RandomStream } from '../../tracer/sampler.ts';
import { drawDirectionsAtHit, type CaseDrawing } from './case-drawing.ts';
import type { CaseFailure, LabCase, Tolerance, Vec3 } from './code-lab-grading.ts';
import { dot, randomDirection, scaled, unit, v } from './lab-vectors.ts';
import type { RefractionEdge } from './refraction-edges.ts';

/**
 * The refraction lab: Snell's law in vector form with total internal reflection (Shirley &
 * Marschner, "Fundamentals of Computer Graphics", 4th ed., §13.1; de Greve, "Reflections and
 * Refractions in Ray Tracing", 2006). The learner writes `refract(d, n, ior)` with n the
 * surface's OUTWARD normal, as an object gives it: inside the glass (d·n > 0) their function
 * must turn the normal toward the ray and use η = n instead of 1/n, as the tracer does
 * (whitted-integrator.ts: `shade` turns the normals, `relativeIndex` picks η, `refract`
 * bends). The answer is the tracer's own `relativeIndex` and `refract`: a unit direction, or
 * null where no ray leaves (total internal reflection).
 */

/**
 * An angle of 1e-7 rad: far below what a picture shows, above the rounding of any way of
 * writing the formula away from the critical angle (the random cases keep away from it).
 */
export const REFRACTION_TOLERANCE: Tolerance = { answer: 'direction', radians: 1e-7, length: 1e-9 };

const GLASS = 1.5;
const DIAMOND = 2.42;

/** Each edge case: the unit direction d, the unit outward normal n, the refractive index. */
const EDGE_CASES: Record<RefractionEdge, [Vec3, Vec3, number]> = {
  // 45° from air into glass: bent toward the normal (28°).
  'into-glass-slanted': [unit(v(1, -1, 0)), v(0, 1, 0), GLASS],
  // Straight in: not bent at all.
  'into-glass-straight': [v(0, -1, 0), v(0, 1, 0), GLASS],
  // 30° from inside glass to air (below the critical angle of 41.8°): bent away from the normal (48.6°).
  'out-of-glass-slanted': [unit(v(Math.tan(Math.PI / 6), 1, 0)), v(0, 1, 0), GLASS],
  // 60° from inside glass: beyond the critical angle, no ray leaves.
  'total-internal-reflection': [unit(v(Math.tan(Math.PI / 3), 1, 0)), v(0, 1, 0), GLASS],
  // 45° into diamond, through a surface tilted along no axis.
  'into-diamond': [unit(v(-1, -2, -1)), unit(v(1, 2, 2)), DIAMOND],
};

const reusable = { d: new Vector3(), n: new Vector3(), out: new Vector3() };

/**
 * The tracer's answer: the normal turned toward the ray (a ray meeting the back of the surface
 * is inside the glass), η by `relativeIndex`, then `refract`; null on total internal reflection.
 */
export function tracerRefract(d: Vec3, outward: Vec3, ior: number): Vec3 | null {
  const entering = dot(outward, d) < 0;
  const n = reusable.n.set(outward.x, outward.y, outward.z);
  if (!entering) n.negate();
  const out = reusable.out;
  return refract(reusable.d.set(d.x, d.y, d.z), n, relativeIndex(entering, ior), out) ? v(out.x, out.y, out.z) : null;
}

/**
 * 1 − η²(1 − cos²θ), whose sign says whether a ray leaves; near 0 (the critical angle) the
 * refracted direction turns by a large angle for a rounding error, so random cases keep away.
 */
function underRoot(d: Vec3, outward: Vec3, ior: number): number {
  const cos = dot(d, outward);
  const eta = cos < 0 ? 1 / ior : ior;
  return 1 - eta * eta * (1 - cos * cos);
}

/** One random case: any direction and outward normal (so about half start inside), an index from water to diamond. */
function randomCase(random: RandomStream): LabCase {
  for (;;) {
    const d = randomDirection(random);
    const n = randomDirection(random);
    const ior = 1.2 + 1.3 * random.next();
    if (Math.abs(dot(d, n)) < 1e-3 || Math.abs(underRoot(d, n, ior)) < 1e-4) continue;
    return { kind: 'random', args: [d, n, ior], expected: tracerRefract(d, n, ior) };
  }
}

/** The lab's cases: the named edge cases first, then `count` seeded random ones. */
export function refractionCases(edges: readonly RefractionEdge[], count: number, seed: number): LabCase[] {
  const random = new RandomStream().reset(seed);
  const named = edges.map((kind): LabCase => ({ kind, args: EDGE_CASES[kind], expected: tracerRefract(...EDGE_CASES[kind]) }));
  return [...named, ...Array.from({ length: count }, () => randomCase(random))];
}

/**
 * How a failing refraction case looks in 3D: d arriving at the surface, the normal as a line
 * through the hit on both sides (the glass's and the air's, as physics books draw it), and
 * the tracer's refracted direction beside the learner's. On total internal reflection the
 * tracer's answer is "no ray": only the learner's is drawn, if they gave one.
 */
export function drawRefractionCase(labCase: LabCase, failure: CaseFailure | null): CaseDrawing {
  const [d, n] = labCase.args as [Vec3, Vec3, number];
  return drawDirectionsAtHit(d, [scaled(n, -1), n], labCase.expected, failure ? failure.gotValue : labCase.expected);
}
