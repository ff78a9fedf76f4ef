import { Vector3 } from 'three';
import { reflect } from '../../tracer/fresnel.ts';
import { RandomStream } from '../../tracer/sampler.ts';
import { drawDirectionsAtHit, type CaseDrawing } from './case-drawing.ts';
import type { CaseFailure, LabCase, Tolerance, Vec3 } from './code-lab-grading.ts';
import { dot, randomDirection, scaled, unit, v } from './lab-vectors.ts';
import type { MirrorEdge } from './mirror-edges.ts';

/**
 * The mirror lab: the direction of a mirrored ray (Shirley & Marschner, "Fundamentals of
 * Computer Graphics", 4th ed., §4.8: r = d − 2(d·n)n). The learner writes `reflect(d, n)`;
 * the answer it is compared with is the tracer's own `reflect` (src/tracer/fresnel.ts),
 * which every mirror and glass hit calls.
 */

/**
 * Both are unit directions: an angle of 1e-9 rad and a length 1e-9 from 1 are far below what
 * a picture shows and far above the rounding of any way of writing the formula.
 */
export const MIRROR_TOLERANCE: Tolerance = { answer: 'direction', radians: 1e-9, length: 1e-9 };

/** Each edge case: the unit direction d and the unit normal n, facing the incoming ray (d·n < 0), as the tracer turns it. */
const EDGE_CASES: Record<MirrorEdge, [Vec3, Vec3]> = {
  // 45° onto a floor: the ray goes up again at 45°.
  'mirror-slanted': [unit(v(1, -1, 0)), v(0, 1, 0)],
  // Straight onto the mirror: straight back.
  'mirror-head-on': [v(0, 0, -1), v(0, 0, 1)],
  // Nearly along the surface: it hardly changes.
  'mirror-grazing': [unit(v(1, -0.01, 0)), v(0, 1, 0)],
  // A normal along no axis: every component of d changes.
  'mirror-tilted': [unit(v(-1, -2, 0.5)), unit(v(1, 2, 2))],
};

const reusable = { d: new Vector3(), n: new Vector3(), out: new Vector3() };

/** The tracer's answer: its own reflect, on three's vectors. */
export function tracerReflect(d: Vec3, n: Vec3): Vec3 {
  const out = reflect(reusable.d.set(d.x, d.y, d.z), reusable.n.set(n.x, n.y, n.z), reusable.out);
  return v(out.x, out.y, out.z);
}

/** One random case: d uniform over all directions, n uniform over those facing it. */
function randomCase(random: RandomStream): LabCase {
  const d = randomDirection(random);
  const drawn = randomDirection(random);
  // A normal at right angles to d (dot 0) has no side; such a draw has probability 0, and would be taken again.
  const n = dot(drawn, d) > 0 ? scaled(drawn, -1) : drawn;
  return { kind: 'random', args: [d, n], expected: tracerReflect(d, n) };
}

/** The lab's cases: the named edge cases first, then `count` seeded random ones. */
export function mirrorCases(edges: readonly MirrorEdge[], count: number, seed: number): LabCase[] {
  const random = new RandomStream().reset(seed);
  const named = edges.map((kind): LabCase => ({ kind, args: EDGE_CASES[kind], expected: tracerReflect(...EDGE_CASES[kind]) }));
  return [...named, ...Array.from({ length: count }, () => randomCase(random))];
}

/**
 * How a failing mirror case looks in 3D: d arriving at the mirror, the normal n it meets,
 * and the tracer's reflected direction beside the learner's (drawDirectionsAtHit).
 */
export function drawMirrorCase(labCase: LabCase, failure: CaseFailure | null): CaseDrawing {
  const [d, n] = labCase.args as [Vec3, Vec3];
  return drawDirectionsAtHit(d, [v(0, 0, 0), n], labCase.expected, failure ? failure.gotValue : labCase.expected);
}
