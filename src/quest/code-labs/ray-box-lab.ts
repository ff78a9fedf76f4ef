import { Vector3 } from 'three';
import { RandomStream } from '../../tracer/sampler.ts';
import { intersectUnitBox } from '../../tracer/shapes/box.ts';
import { FOUND, REACH, unitSpan } from '../../tracer/shapes/unit-span.ts';
import { distanceOf, drawHitsOnRay, type CaseDrawing } from './case-drawing.ts';
import type { CaseFailure, LabCase, Tolerance, Vec3 } from './code-lab-grading.ts';
import type { RayBoxEdge } from './ray-box-edges.ts';

/**
 * The AABB slab test lab (Kay & Kajiya, "Ray Tracing Complex Scenes", SIGGRAPH 1986;
 * Shirley & Marschner, "Fundamentals of Computer Graphics", 4th ed., §12.3.1). The learner
 * writes `hitBox(origin, direction, boxMin, boxMax)`: where the ray enters the box (t_near),
 * the exit t_far when it starts inside, or null. The answer it is compared with is the
 * tracer's own box test (src/tracer/shapes/box.ts), which decides the two ties this way:
 * a ray that just touches an edge or a corner hits there (t_near ≤ t_far, as for the
 * tangent ray of the sphere lab), and a ray that runs exactly in the plane of a face
 * misses: 0 · ∞ is NaN there, and the tracer's test counts NaN as no hit.
 */

/** As the sphere lab's: t is a distance in metres, 1e-6 of it far below what a picture shows. */
export const RAY_BOX_TOLERANCE: Tolerance = { answer: 'number', relative: 1e-6 };

const v = (x: number, y: number, z: number): Vec3 => ({ x, y, z });
const unit = (x: number, y: number, z: number): Vec3 => {
  const length = Math.hypot(x, y, z);
  return v(x / length, y / length, z / length);
};

/** The box of most edge cases: −1 to 1 on every axis, whose centre and size scale to the tracer's unit cube exactly. */
const MIN = v(-1, -1, -1);
const MAX = v(1, 1, 1);

/**
 * Each edge case: origin, unit direction, box min, box max. The parallel rays go along
 * (0, 0.8, 0.6), with direction.x exactly 0; the edge-touching ray's entry and exit are the
 * same number (1/d.x = 1/d.y), so t_near = t_far exactly.
 */
const EDGE_CASES: Record<RayBoxEdge, [Vec3, Vec3, Vec3, Vec3]> = {
  'box-hit-from-outside': [v(-3, -2, -6), unit(3, 2, 6), MIN, MAX],
  'box-miss': [v(-3, 2, -6), unit(3, 2, 6), MIN, MAX],
  'box-behind': [v(3, 2, 6), unit(3, 2, 6), MIN, MAX],
  'inside-box': [v(0.2, -0.3, 0.5), unit(3, 2, 6), MIN, MAX],
  'negative-direction': [v(2, 5, 4), unit(-2, -6, -3), v(0, 0, 0), v(2, 1, 3)],
  'parallel-inside-slab': [v(0.5, -4, -3), v(0, 0.8, 0.6), MIN, MAX],
  'parallel-outside-slab': [v(1.5, -4, -3), v(0, 0.8, 0.6), MIN, MAX],
  'in-face-plane': [v(1, -4, -3), v(0, 0.8, 0.6), MIN, MAX],
  'touches-edge': [v(-2, 0, -1), unit(1, 1, 1), MIN, MAX],
};

const reusable = { o: new Vector3(), d: new Vector3(), size: new Vector3(), span: unitSpan() };

/**
 * The tracer's answer: its unit cube (−0.5 to 0.5, centred on the origin) after moving the
 * box's centre to the origin and dividing each axis by the box's size on it. Mapping origin
 * and direction by the same linear map leaves every t unchanged, so the t found is the one
 * on the learner's box.
 */
export function tracerHitBox(origin: Vec3, direction: Vec3, boxMin: Vec3, boxMax: Vec3): number | null {
  const { o, d, size, span } = reusable;
  size.set(boxMax.x - boxMin.x, boxMax.y - boxMin.y, boxMax.z - boxMin.z);
  o.set(origin.x - (boxMin.x + boxMax.x) / 2, origin.y - (boxMin.y + boxMax.y) / 2, origin.z - (boxMin.z + boxMax.z) / 2).divide(size);
  d.set(direction.x, direction.y, direction.z).divide(size);
  span[REACH] = Infinity;
  return intersectUnitBox(o, d, span) ? span[FOUND] : null;
}

function edgeCase(kind: RayBoxEdge): LabCase {
  const args = EDGE_CASES[kind];
  return { kind, args, expected: tracerHitBox(...args) };
}

/** A direction uniform over the sphere of directions (Archimedes: z uniform in [-1, 1]). */
function randomDirection(random: RandomStream): Vec3 {
  const z = 2 * random.next() - 1;
  const phi = 2 * Math.PI * random.next();
  const r = Math.sqrt(1 - z * z);
  return v(r * Math.cos(phi), r * Math.sin(phi), z);
}

/**
 * One random case: a box somewhere in a 10 m space, 0.2 to 3 m on each side, and a ray
 * from a random point toward a point near the box (so about half hit), sometimes from
 * inside it. Rays whose answer a rounding error could flip are drawn again: entry and exit
 * within a millionth of each other (an edge or corner, tested exactly by `touches-edge`),
 * or an origin within a micrometre of a face.
 */
function randomCase(random: RandomStream): LabCase {
  for (;;) {
    const size = v(0.2 + 2.8 * random.next(), 0.2 + 2.8 * random.next(), 0.2 + 2.8 * random.next());
    const boxMin = v(10 * random.next() - 5, 10 * random.next() - 5, 10 * random.next() - 5);
    const boxMax = v(boxMin.x + size.x, boxMin.y + size.y, boxMin.z + size.z);
    const centre = v(boxMin.x + size.x / 2, boxMin.y + size.y / 2, boxMin.z + size.z / 2);
    const inside = random.next() < 0.15;
    const origin = inside
      ? v(boxMin.x + size.x * random.next(), boxMin.y + size.y * random.next(), boxMin.z + size.z * random.next())
      : offset(centre, randomDirection(random), 2 + 6 * random.next());
    const target = offset(centre, randomDirection(random), 2 * random.next());
    const aim = v(target.x - origin.x, target.y - origin.y, target.z - origin.z);
    const length = Math.hypot(aim.x, aim.y, aim.z);
    if (length < 1e-3) continue;
    const direction = v(aim.x / length, aim.y / length, aim.z / length);
    if (ambiguous(origin, direction, boxMin, boxMax)) continue;
    return { kind: 'random-box', args: [origin, direction, boxMin, boxMax], expected: tracerHitBox(origin, direction, boxMin, boxMax) };
  }
}

const offset = (from: Vec3, direction: Vec3, distance: number): Vec3 =>
  v(from.x + distance * direction.x, from.y + distance * direction.y, from.z + distance * direction.z);

/** The textbook's slab interval, to find the rays on a knife's edge; the answer itself is the tracer's. */
function ambiguous(origin: Vec3, direction: Vec3, boxMin: Vec3, boxMax: Vec3): boolean {
  let near = -Infinity;
  let far = Infinity;
  for (const axis of ['x', 'y', 'z'] as const) {
    const t0 = (boxMin[axis] - origin[axis]) / direction[axis];
    const t1 = (boxMax[axis] - origin[axis]) / direction[axis];
    near = Math.max(near, Math.min(t0, t1));
    far = Math.min(far, Math.max(t0, t1));
  }
  return Math.abs(far - near) <= 1e-6 * Math.max(1, Math.abs(far)) || Math.abs(near) < 1e-6 || Math.abs(far) < 1e-6;
}

/** The lab's cases: the named edge cases first (the misconceptions, named in the result), then `count` seeded random ones. */
export function rayBoxCases(edges: readonly RayBoxEdge[], count: number, seed: number): LabCase[] {
  const random = new RandomStream().reset(seed);
  return [...edges.map(edgeCase), ...Array.from({ length: count }, () => randomCase(random))];
}

/**
 * How a failing ray–box case looks in 3D: the ray from its origin, on past the box; the box
 * as a wireframe; the tracer's hit and the learner's on the ray (drawHitsOnRay).
 */
export function drawRayBoxCase(labCase: LabCase, failure: CaseFailure | null): CaseDrawing {
  const [origin, direction, min, max] = labCase.args as [Vec3, Vec3, Vec3, Vec3];
  const expected = distanceOf(labCase.expected);
  const got = distanceOf(failure ? failure.gotValue : labCase.expected);
  // Far enough to pass the box's farthest corner from the origin.
  const corner = v(
    Math.max(Math.abs(min.x - origin.x), Math.abs(max.x - origin.x)),
    Math.max(Math.abs(min.y - origin.y), Math.abs(max.y - origin.y)),
    Math.max(Math.abs(min.z - origin.z), Math.abs(max.z - origin.z)),
  );
  const reach = Math.max(Math.hypot(corner.x, corner.y, corner.z), expected ?? 0, got ?? 0) * 1.15;
  return drawHitsOnRay(origin, direction, reach, expected, got, [{ kind: 'box', min, max }]);
}
