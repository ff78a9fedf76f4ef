import type { Vector3 } from 'three';
import type { Ray } from '../ray.ts';
import { FOUND, REACH, type UnitSpan } from './unit-span.ts';

/**
 * The unit square in the XZ plane, normal +Y, hit from both sides (spec §1), placed in the
 * world by the world-to-object rows `m` (Shape's: m[0..3] the x row, m[4..7] y, m[8..11] z)
 * and moving by `velocity` per unit of time (null: it stands still). Whether the world ray
 * meets it at a t in (0, span[REACH]); that t goes to span[FOUND], the ray in object space
 * to `o` and `d` (as Shape.toLocal writes it).
 *
 * The y row comes first: the ray's height above the plane and how fast it climbs give t, and
 * only a t within reach pays for the x and z rows. Its arithmetic is Shape.toLocal's and the
 * unit square's test in their order, so a hit is the same to the bit; the plane's world box
 * is not tested first, as it rejects a ray no sooner than the y row does and costs more (the
 * walls of a Cornell box are five of its seven objects).
 */
export function intersectPlacedPlane(m: Float64Array, velocity: Vector3 | null, ray: Ray, o: Vector3, d: Vector3, span: UnitSpan): boolean {
  const { x: ox, y: oy, z: oz } = ray.origin;
  const { x: dx, y: dy, z: dz } = ray.direction;
  let height = m[4] * ox + m[5] * oy + m[6] * oz + m[7];
  if (velocity) height += velocity.y * ray.time;
  const climb = m[4] * dx + m[5] * dy + m[6] * dz;
  if (climb === 0) return false;
  const t = -height / climb;
  if (!(t > 0 && t < span[REACH])) return false;
  o.set(m[0] * ox + m[1] * oy + m[2] * oz + m[3], height, m[8] * ox + m[9] * oy + m[10] * oz + m[11]);
  if (velocity) {
    o.x += velocity.x * ray.time;
    o.z += velocity.z * ray.time;
  }
  d.set(m[0] * dx + m[1] * dy + m[2] * dz, climb, m[8] * dx + m[9] * dy + m[10] * dz);
  const x = o.x + t * d.x;
  const z = o.z + t * d.z;
  if (!(Math.abs(x) <= 0.5 && Math.abs(z) <= 0.5)) return false;
  span[FOUND] = t;
  return true;
}

/** The unit plane's normal. */
export const UNIT_PLANE_NORMAL: readonly [number, number, number] = [0, 1, 0];
