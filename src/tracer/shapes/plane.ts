import type { Vector3 } from 'three';
import { FOUND, REACH, type UnitSpan } from './unit-span.ts';

/**
 * The unit square in the XZ plane, normal +Y; hit from both sides (spec §1).
 * Whether a t in (0, span[REACH]) meets it; that t goes to span[FOUND].
 */
export function intersectUnitPlane(o: Vector3, d: Vector3, span: UnitSpan): boolean {
  if (d.y === 0) return false;
  const t = -o.y / d.y;
  if (!(t > 0 && t < span[REACH])) return false;
  const x = o.x + t * d.x;
  const z = o.z + t * d.z;
  if (!(Math.abs(x) <= 0.5 && Math.abs(z) <= 0.5)) return false;
  span[FOUND] = t;
  return true;
}

/** The unit plane's normal. */
export const UNIT_PLANE_NORMAL: readonly [number, number, number] = [0, 1, 0];
