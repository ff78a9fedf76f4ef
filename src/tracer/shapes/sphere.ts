import type { Vector3 } from 'three';

/**
 * The unit sphere: radius 0.5 at the origin (an ellipsoid once scaled).
 * Returns the nearest t in (0, tMax) where o + t·d meets it, or Infinity.
 */
export function intersectUnitSphere(o: Vector3, d: Vector3, tMax: number): number {
  // |o + t·d|² = r²  →  a·t² + 2·b·t + c = 0, solved in the half-b form.
  const a = d.x * d.x + d.y * d.y + d.z * d.z;
  const b = o.x * d.x + o.y * d.y + o.z * d.z;
  const c = o.x * o.x + o.y * o.y + o.z * o.z - 0.25;
  const disc = b * b - a * c;
  if (disc < 0) return Infinity;
  const root = Math.sqrt(disc);
  let t = (-b - root) / a;
  if (t <= 0) t = (-b + root) / a; // the ray starts inside (refraction)
  return t > 0 && t < tMax ? t : Infinity;
}

/** The outward normal at a point p on the unit sphere (not normalized). */
export function unitSphereNormal(p: Vector3, out: Vector3): Vector3 {
  return out.copy(p);
}
