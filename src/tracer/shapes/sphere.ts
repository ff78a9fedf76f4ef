import type { Vector3 } from 'three';
import { FOUND, REACH, type UnitSpan } from './unit-span.ts';

/**
 * The unit sphere: radius 0.5 at the origin (an ellipsoid once scaled).
 * Whether o + t·d meets it for a t in (0, span[REACH]); the nearest such t goes to span[FOUND].
 */
export function intersectUnitSphere(o: Vector3, d: Vector3, span: UnitSpan): boolean {
  // |o + t·d|² = r²  →  a·t² + 2·b·t + c = 0, solved in the half-b form.
  const a = d.x * d.x + d.y * d.y + d.z * d.z;
  const b = o.x * d.x + o.y * d.y + o.z * d.z;
  const c = o.x * o.x + o.y * o.y + o.z * o.z - 0.25;
  const disc = b * b - a * c;
  if (disc < 0) return false;
  const root = Math.sqrt(disc);
  let t = (-b - root) / a;
  if (t <= 0) t = (-b + root) / a; // the ray starts inside (refraction)
  if (!(t > 0 && t < span[REACH])) return false;
  span[FOUND] = t;
  return true;
}

/** The outward normal at a point p on the unit sphere (not normalized). */
export function unitSphereNormal(p: Vector3, out: Vector3): Vector3 {
  return out.copy(p);
}
