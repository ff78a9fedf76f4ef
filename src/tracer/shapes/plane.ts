import type { Vector3 } from 'three';

/**
 * The unit square in the XZ plane, normal +Y; hit from both sides (spec §1).
 * The nearest t in (0, tMax), or Infinity.
 */
export function intersectUnitPlane(o: Vector3, d: Vector3, tMax: number): number {
  if (d.y === 0) return Infinity;
  const t = -o.y / d.y;
  if (!(t > 0 && t < tMax)) return Infinity;
  const x = o.x + t * d.x;
  const z = o.z + t * d.z;
  return Math.abs(x) <= 0.5 && Math.abs(z) <= 0.5 ? t : Infinity;
}

export function unitPlaneNormal(out: Vector3): Vector3 {
  return out.set(0, 1, 0);
}
