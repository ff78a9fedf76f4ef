import { RandomStream } from '../../tracer/sampler.ts';
import type { CaseDrawing } from './case-drawing.ts';
import type { CaseFailure, LabCase, Tolerance, Vec3 } from './code-lab-grading.ts';
import { randomDirection, unit, v } from './lab-vectors.ts';
import { tracerHitSphere } from './ray-sphere-lab.ts';
import type { ShadowEdge } from './shadow-edges.ts';

/**
 * The shadow-test lab (Whitted, "An Improved Illumination Model for Shaded Display", 1980;
 * Shirley & Marschner, "Fundamentals of Computer Graphics", 4th ed., §4.7). The learner
 * writes `inShadow(point, toLight, distanceToLight, spheres)`: whether a sphere blocks the
 * shadow ray from the point toward the light. The answer it is compared with follows the
 * tracer's own rule (src/tracer/shadow-tester.ts, `Shape.occludes`): an object blocks when
 * the shadow ray meets it at a t with 0 < t < the ray's reach, and the tracer's sphere test
 * (tracerHitSphere) finds that t. The tracer starts the shadow ray ε off the surface (so the
 * surface cannot shadow itself through rounding: shading-frame.ts `offsetOrigin`) and skips
 * the convex object the ray leaves; the cases give `point` already moved off the surface,
 * so the point's own sphere only meets the ray at t < 0. The tracer's reach stops ε short of
 * the light; the random cases keep every hit far from the light, so that ε changes nothing.
 */

export interface Sphere {
  center: Vec3;
  radius: number;
}

export const SHADOW_TOLERANCE: Tolerance = { answer: 'boolean' };

/** The tracer's answer: some sphere is met in front of the point and before the light. */
export function tracerInShadow(point: Vec3, toLight: Vec3, distanceToLight: number, spheres: readonly Sphere[]): boolean {
  return spheres.some((sphere) => firstHit(point, toLight, sphere) < distanceToLight);
}

/** Where the tracer's sphere test meets the shadow ray (t > 0), Infinity when it does not. */
const firstHit = (point: Vec3, toLight: Vec3, sphere: Sphere): number => tracerHitSphere(point, toLight, sphere.center, sphere.radius) ?? Infinity;

const ball = (x: number, y: number, z: number, radius: number): Sphere => ({ center: v(x, y, z), radius });

/** The point: on a floor at y = 0, moved ε = 1e-4 m up, as the tracer moves a shadow ray's start. */
const FLOOR_POINT = v(0, 1e-4, 0);
const UP = v(0, 1, 0);
const BEHIND = ball(0, -2, 0, 1);
const BEYOND = ball(0, 6, 0, 1);

/**
 * Each edge case: point, unit direction to the light, distance to the light, spheres. The
 * light is 4 m straight above the point except for `own-sphere`, whose point lies on top of a
 * ball of radius 1 (moved ε out along its normal) with the light up and to the side.
 */
const EDGE_CASES: Record<ShadowEdge, [Vec3, Vec3, number, Sphere[]]> = {
  blocked: [FLOOR_POINT, UP, 4, [ball(0, 2, 0, 0.5)]],
  'nothing-in-the-way': [FLOOR_POINT, UP, 4, [ball(1.5, 2, 0, 0.5)]],
  'beyond-the-light': [FLOOR_POINT, UP, 4, [BEYOND]],
  'behind-the-point': [FLOOR_POINT, UP, 4, [BEHIND]],
  'own-sphere': [v(0, 1 + 1e-4, 0), unit(v(1, 2, 0)), 5, [ball(0, 0, 0, 1)]],
  'several-spheres': [FLOOR_POINT, UP, 4, [BEHIND, BEYOND, ball(0.2, 3, 0, 0.5)]],
};

function edgeCase(kind: ShadowEdge): LabCase {
  const args = EDGE_CASES[kind];
  return { kind, args, expected: tracerInShadow(...args) };
}

const along = (origin: Vec3, direction: Vec3, t: number): Vec3 => v(origin.x + t * direction.x, origin.y + t * direction.y, origin.z + t * direction.z);

/**
 * One random case: a point in a 10 m box, a light 1 to 8 m away in a random direction, and 1
 * to 4 spheres placed near the line through them, before, between and beyond (so about half
 * the cases are in shadow). Cases a rounding error could flip are drawn again: a point inside
 * or within a millimetre of a sphere, a ray that grazes a sphere, a hit within a millimetre
 * of the light.
 */
function randomCase(random: RandomStream): LabCase {
  for (;;) {
    const point = v(10 * random.next() - 5, 10 * random.next() - 5, 10 * random.next() - 5);
    const toLight = randomDirection(random);
    const distance = 1 + 7 * random.next();
    const count = 1 + Math.floor(4 * random.next());
    const spheres = Array.from({ length: count }, (): Sphere => {
      const radius = 0.2 + 1.3 * random.next();
      const onLine = along(point, toLight, -3 + (distance + 6) * random.next());
      const aside = randomDirection(random);
      return { center: along(onLine, aside, 2 * radius * random.next()), radius };
    });
    if (spheres.some((sphere) => ambiguous(point, toLight, distance, sphere))) continue;
    return { kind: 'random-shadow', args: [point, toLight, distance, spheres], expected: tracerInShadow(point, toLight, distance, spheres) };
  }
}

/** The textbook's quadratic, to find the cases on a knife's edge; the answer itself is the tracer's. */
function ambiguous(point: Vec3, toLight: Vec3, distance: number, { center, radius }: Sphere): boolean {
  const oc = v(point.x - center.x, point.y - center.y, point.z - center.z);
  const b = oc.x * toLight.x + oc.y * toLight.y + oc.z * toLight.z;
  const c = oc.x * oc.x + oc.y * oc.y + oc.z * oc.z - radius * radius;
  if (Math.sqrt(oc.x * oc.x + oc.y * oc.y + oc.z * oc.z) < radius + 1e-3) return true;
  const disc = b * b - c;
  if (Math.abs(disc) <= 1e-6 * (b * b + Math.abs(c))) return true;
  if (disc < 0) return false;
  const roots = [-b - Math.sqrt(disc), -b + Math.sqrt(disc)];
  return roots.some((t) => Math.abs(t - distance) < 1e-3);
}

/** The lab's cases: the named edge cases first (the misconceptions, named in the result), then `count` seeded random ones. */
export function shadowCases(edges: readonly ShadowEdge[], count: number, seed: number): LabCase[] {
  const random = new RandomStream().reset(seed);
  return [...edges.map(edgeCase), ...Array.from({ length: count }, () => randomCase(random))];
}

/**
 * How a failing shadow case looks in 3D: the shadow ray from the point to the light, the
 * spheres, and where it is blocked: the tracer's first blocking hit (expected). When the
 * learner said "in shadow" where nothing blocks, the sphere the line crosses nearest the
 * point (behind it or beyond the light) is marked as the hit that answer counted (got), with
 * a segment along the line to it.
 */
export function drawShadowCase(labCase: LabCase, failure: CaseFailure | null): CaseDrawing {
  const [point, toLight, distance, spheres] = labCase.args as [Vec3, Vec3, number, Sphere[]];
  const drawing: CaseDrawing = {
    segments: [{ from: point, to: along(point, toLight, distance), mark: 'ray', arrow: true }],
    points: [],
    shapes: spheres.map(({ center, radius }) => ({ kind: 'sphere' as const, center, radius })),
  };
  const blocker = Math.min(...spheres.map((sphere) => firstHit(point, toLight, sphere)));
  if (blocker < distance) drawing.points.push({ at: along(point, toLight, blocker), mark: 'expected' });
  else if (failure?.gotValue === true) {
    const crossing = nearestCrossing(point, toLight, spheres);
    if (crossing !== null) {
      drawing.points.push({ at: along(point, toLight, crossing), mark: 'got' });
      drawing.segments.push({ from: point, to: along(point, toLight, crossing), mark: 'got' });
    }
  }
  return drawing;
}

/** The t (of either sign) where the whole line through the point first crosses a sphere, nearest the point; null when it crosses none. */
function nearestCrossing(point: Vec3, toLight: Vec3, spheres: readonly Sphere[]): number | null {
  let nearest: number | null = null;
  for (const { center, radius } of spheres) {
    const oc = v(point.x - center.x, point.y - center.y, point.z - center.z);
    const b = oc.x * toLight.x + oc.y * toLight.y + oc.z * toLight.z;
    const disc = b * b - (oc.x * oc.x + oc.y * oc.y + oc.z * oc.z - radius * radius);
    if (disc < 0) continue;
    for (const t of [-b - Math.sqrt(disc), -b + Math.sqrt(disc)]) if (nearest === null || Math.abs(t) < Math.abs(nearest)) nearest = t;
  }
  return nearest;
}
