import { Vector3 } from 'three';
import { RandomStream } from '../../tracer/sampler.ts';
import { intersectUnitSphere } from '../../tracer/shapes/sphere.ts';
import { FOUND, REACH, unitSpan } from '../../tracer/shapes/unit-span.ts';
import { distanceOf, drawHitsOnRay, type CaseDrawing } from './case-drawing.ts';
import type { CaseFailure, LabCase, Tolerance, Vec3 } from './code-lab-grading.ts';
import type { RaySphereEdge } from './ray-sphere-edges.ts';
import { randomDirection, v } from './lab-vectors.ts';

/**
 * The first code lab: ray–sphere intersection (Shirley & Marschner, "Fundamentals of
 * Computer Graphics", 4th ed., §4.4.1; "Ray Tracing in One Weekend" §5–6). The learner writes
 * `hitSphere(origin, direction, center, radius)`: the nearest t > 0 where origin + t·direction
 * lies on the sphere, or null. The answer it is compared with is the tracer's own sphere test.
 */

/**
 * t is a distance along a unit direction; 1e-6 of it (or 1e-6 m for t below 1) is far below
 * anything a picture shows, and far above the rounding of either form of the formula.
 */
export const RAY_SPHERE_TOLERANCE: Tolerance = { answer: 'number', relative: 1e-6 };

/** Each edge case: origin, unit direction, centre, radius. The tangent ray's discriminant is exactly 0 in both forms of the formula. */
const EDGE_CASES: Record<RaySphereEdge, [Vec3, Vec3, Vec3, number]> = {
  'hit-from-outside': [v(0, 0, -5), v(0, 0, 1), v(0, 0, 0), 1],
  miss: [v(0, 3, -5), v(0, 0, 1), v(0, 0, 0), 1],
  'sphere-behind': [v(0, 0, 5), v(0, 0, 1), v(0, 0, 0), 1],
  'inside-sphere': [v(0, 0, 0.5), v(0, 0, 1), v(0, 0, 0), 2],
  tangent: [v(0, 1, -5), v(0, 0, 1), v(0, 0, 0), 1],
  'off-centre': [v(1, 2, 0), v(1, 0, 0), v(4, 2, 0), 0.5],
};

const reusable = { o: new Vector3(), d: new Vector3(), span: unitSpan() };

/**
 * The tracer's answer: its unit sphere (radius 0.5 at the origin) after moving the centre to
 * the origin and scaling by 1/(2·radius). Scaling origin and direction alike leaves every t
 * unchanged, so the t found is the one on the learner's sphere.
 */
export function tracerHitSphere(origin: Vec3, direction: Vec3, center: Vec3, radius: number): number | null {
  const scale = 1 / (2 * radius);
  const { o, d, span } = reusable;
  o.set(origin.x - center.x, origin.y - center.y, origin.z - center.z).multiplyScalar(scale);
  d.set(direction.x, direction.y, direction.z).multiplyScalar(scale);
  span[REACH] = Infinity;
  return intersectUnitSphere(o, d, span) ? span[FOUND] : null;
}

function edgeCase(kind: RaySphereEdge): LabCase {
  const args = EDGE_CASES[kind];
  return { kind, args, expected: tracerHitSphere(...args) };
}

/**
 * One random case: a sphere somewhere in a 10 m box and a ray from a random point toward a
 * point near the sphere (so about half hit), sometimes from inside it. Rays that graze the
 * sphere are drawn again: there t changes by metres for a rounding error, and the tangent
 * edge case tests them exactly.
 */
function randomCase(random: RandomStream): LabCase {
  for (;;) {
    const center = v(10 * random.next() - 5, 10 * random.next() - 5, 10 * random.next() - 5);
    const radius = 0.2 + 2 * random.next();
    const inside = random.next() < 0.15;
    const away = inside ? 0.9 * radius * random.next() : radius + 6 * random.next();
    const offset = randomDirection(random);
    const origin = v(center.x + away * offset.x, center.y + away * offset.y, center.z + away * offset.z);
    const aim = randomDirection(random);
    const spread = 2 * radius * random.next();
    const target = v(center.x + spread * aim.x - origin.x, center.y + spread * aim.y - origin.y, center.z + spread * aim.z - origin.z);
    const length = Math.hypot(target.x, target.y, target.z);
    if (length < 1e-3) continue;
    const direction = v(target.x / length, target.y / length, target.z / length);
    if (grazes(origin, direction, center, radius)) continue;
    return { kind: 'random', args: [origin, direction, center, radius], expected: tracerHitSphere(origin, direction, center, radius) };
  }
}

/** The discriminant within a millionth of its terms' size of 0: a ray that all but touches the sphere. */
function grazes(origin: Vec3, direction: Vec3, center: Vec3, radius: number): boolean {
  const oc = v(origin.x - center.x, origin.y - center.y, origin.z - center.z);
  const b = oc.x * direction.x + oc.y * direction.y + oc.z * direction.z;
  const c = oc.x * oc.x + oc.y * oc.y + oc.z * oc.z - radius * radius;
  return Math.abs(b * b - c) <= 1e-6 * (b * b + Math.abs(c));
}

/** The lab's cases: the named edge cases first (the misconceptions, named in the result), then `count` seeded random ones. */
export function raySphereCases(edges: readonly RaySphereEdge[], count: number, seed: number): LabCase[] {
  const random = new RandomStream().reset(seed);
  return [...edges.map(edgeCase), ...Array.from({ length: count }, () => randomCase(random))];
}

/**
 * How a failing ray–sphere case looks in 3D: the ray from its origin, on past the sphere; the
 * sphere; the tracer's hit and the learner's on the ray (drawHitsOnRay).
 */
export function drawRaySphereCase(labCase: LabCase, failure: CaseFailure | null): CaseDrawing {
  const [origin, direction, center, radius] = labCase.args as [Vec3, Vec3, Vec3, number];
  const expected = distanceOf(labCase.expected);
  const got = distanceOf(failure ? failure.gotValue : labCase.expected);
  const toCentre = Math.hypot(center.x - origin.x, center.y - origin.y, center.z - origin.z);
  const reach = Math.max(toCentre + radius, expected ?? 0, got ?? 0) * 1.15;
  return drawHitsOnRay(origin, direction, reach, expected, got, [{ kind: 'sphere', center, radius }]);
}
