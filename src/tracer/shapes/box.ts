import type { Vector3 } from 'three';
import { FOUND, REACH, type UnitSpan } from './unit-span.ts';

/**
 * The unit cube, 1×1×1 centred on the origin (slab test in object space; the exit
 * distance is the hit when the ray starts inside). Whether a t in (0, span[REACH]) meets
 * it; the nearest goes to span[FOUND].
 */
export function intersectUnitBox(o: Vector3, d: Vector3, span: UnitSpan): boolean {
  let inv = 1 / d.x;
  let t0 = (-0.5 - o.x) * inv;
  let t1 = (0.5 - o.x) * inv;
  let near = Math.min(t0, t1);
  let far = Math.max(t0, t1);
  inv = 1 / d.y;
  t0 = (-0.5 - o.y) * inv;
  t1 = (0.5 - o.y) * inv;
  near = Math.max(near, Math.min(t0, t1));
  far = Math.min(far, Math.max(t0, t1));
  inv = 1 / d.z;
  t0 = (-0.5 - o.z) * inv;
  t1 = (0.5 - o.z) * inv;
  near = Math.max(near, Math.min(t0, t1));
  far = Math.min(far, Math.max(t0, t1));
  if (!(near <= far) || far <= 0) return false;
  const t = near > 0 ? near : far;
  if (!(t < span[REACH])) return false;
  span[FOUND] = t;
  return true;
}

/** The outward unit normals of the unit cube's faces, in the order unitBoxFace numbers them. */
export const UNIT_BOX_FACE_NORMALS: readonly (readonly [number, number, number])[] = [
  [1, 0, 0],
  [-1, 0, 0],
  [0, 1, 0],
  [0, -1, 0],
  [0, 0, 1],
  [0, 0, -1],
];

/**
 * The face of the unit cube a point p of its surface lies on, the axis it lies farthest out
 * on: 0 +x, 1 −x, 2 +y, 3 −y, 4 +z, 5 −z (UNIT_BOX_FACE_NORMALS).
 */
export function unitBoxFace(p: Vector3): number {
  const ax = Math.abs(p.x);
  const ay = Math.abs(p.y);
  const az = Math.abs(p.z);
  if (ax >= ay && ax >= az) return p.x < 0 ? 1 : 0;
  if (ay >= az) return p.y < 0 ? 3 : 2;
  return p.z < 0 ? 5 : 4;
}
