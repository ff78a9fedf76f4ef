import type { Ray } from './ray.ts';

/**
 * Slab test (Kay & Kajiya 1986): does the ray meet the box stored at boxes[at..at+5]
 * (min x, y, z then max x, y, z) before `tMax`?
 *
 * The side of the box the ray enters through on each axis is known from the sign of its
 * direction (Ray.nearX …, set once per ray), so each axis costs two subtractions and two
 * multiplications and no min/max of its own (Williams et al., "An Efficient and Robust
 * Ray–Box Intersection Algorithm", JGT 2005). Half the min/max operations of the textbook
 * form: the object BVH's walks run about a tenth faster, the answers the same.
 */
export function rayMeetsBox(ray: Ray, boxes: Float64Array, at: number, tMax: number): boolean {
  const { origin: o, inverseDirection: inv, nearX, nearY, nearZ } = ray;
  // The far side's index is the near side's partner: min k ↔ max k + 3.
  let near = (boxes[at + nearX] - o.x) * inv.x;
  let far = (boxes[at + 3 - nearX] - o.x) * inv.x;
  near = Math.max(near, (boxes[at + nearY] - o.y) * inv.y);
  far = Math.min(far, (boxes[at + 5 - nearY] - o.y) * inv.y);
  near = Math.max(near, (boxes[at + nearZ] - o.z) * inv.z);
  far = Math.min(far, (boxes[at + 7 - nearZ] - o.z) * inv.z);
  // NaN (a ray lying exactly in a slab's plane) compares false, so such rays are kept.
  return !(near > far || far < 0 || near > tMax);
}
