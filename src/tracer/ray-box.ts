import type { Ray } from './ray.ts';

/**
 * Slab test (Kay & Kajiya 1986): does the ray meet the box stored at boxes[at..at+5]
 * (min x, y, z then max x, y, z) before `tMax`?
 */
export function rayMeetsBox(ray: Ray, boxes: Float64Array, at: number, tMax: number): boolean {
  const { origin: o, inverseDirection: inv } = ray;
  let t0 = (boxes[at] - o.x) * inv.x;
  let t1 = (boxes[at + 3] - o.x) * inv.x;
  let near = Math.min(t0, t1);
  let far = Math.max(t0, t1);
  t0 = (boxes[at + 1] - o.y) * inv.y;
  t1 = (boxes[at + 4] - o.y) * inv.y;
  near = Math.max(near, Math.min(t0, t1));
  far = Math.min(far, Math.max(t0, t1));
  t0 = (boxes[at + 2] - o.z) * inv.z;
  t1 = (boxes[at + 5] - o.z) * inv.z;
  near = Math.max(near, Math.min(t0, t1));
  far = Math.min(far, Math.max(t0, t1));
  // NaN (a ray lying exactly in a slab's plane) compares false, so such rays are kept.
  return !(near > far || far < 0 || near > tMax);
}
