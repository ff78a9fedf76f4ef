import type { Vector3 } from 'three';
import { FOUND, REACH, type UnitSpan } from './unit-span.ts';

/**
 * The unit capped cylinder: radius 0.5, height 1, axis Y, centred on the origin.
 * Whether a t in (0, span[REACH]) meets it; the nearest goes to span[FOUND].
 */
export function intersectUnitCylinder(o: Vector3, d: Vector3, span: UnitSpan): boolean {
  const tMax = span[REACH];
  let best = tMax;
  // Side: x² + z² = r² with |y| ≤ 0.5 (half-b quadratic).
  const a = d.x * d.x + d.z * d.z;
  if (a > 0) {
    const b = o.x * d.x + o.z * d.z;
    const c = o.x * o.x + o.z * o.z - 0.25;
    const disc = b * b - a * c;
    if (disc >= 0) {
      const root = Math.sqrt(disc);
      best = nearerSideHit((-b - root) / a, o, d, best);
      best = nearerSideHit((-b + root) / a, o, d, best);
    }
  }
  // Caps: y = ±0.5 with x² + z² ≤ r².
  if (d.y !== 0) {
    best = nearerCapHit((-0.5 - o.y) / d.y, o, d, best);
    best = nearerCapHit((0.5 - o.y) / d.y, o, d, best);
  }
  if (!(best < tMax)) return false;
  span[FOUND] = best;
  return true;
}

/** The outward normal at p: a cap when p is nearer a cap's plane (0.5 − |y|) than the side (0.5 − radius). */
export function unitCylinderNormal(p: Vector3, out: Vector3): Vector3 {
  if (Math.abs(p.y) > Math.sqrt(p.x * p.x + p.z * p.z)) return out.set(0, Math.sign(p.y), 0);
  return out.set(p.x, 0, p.z);
}

function nearerSideHit(t: number, o: Vector3, d: Vector3, best: number): number {
  return t > 0 && t < best && Math.abs(o.y + t * d.y) <= 0.5 ? t : best;
}

function nearerCapHit(t: number, o: Vector3, d: Vector3, best: number): number {
  if (!(t > 0 && t < best)) return best;
  const x = o.x + t * d.x;
  const z = o.z + t * d.z;
  return x * x + z * z <= 0.25 ? t : best;
}
