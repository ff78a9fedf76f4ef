import type { Vector3 } from 'three';
import type { MeshAccel } from './mesh-accel.ts';
import { isLeaf, meetsTriangle, nodeMeets, type PackedRoot, ray, setWalkRay, UINT32_PER_NODE } from './mesh-walk.ts';

/**
 * The nearest hit of o + t·d, t < tMax, on the model, as three-mesh-bvh's `raycastFirst`
 * (DoubleSide, near 0) finds it, without its allocations (mesh-walk.ts): the same walk,
 * child for child, so the same triangle wins, ties included. At an inner node the child on
 * the ray's side of the split axis goes first, and the other is skipped when the first one's
 * hit lies before the other's box along that axis; a leaf keeps its first nearest triangle;
 * of two children's hits at the same distance the first child's, of two roots' the first
 * root's. Returns whether there is one; its distance along the unit direction and its
 * triangle are in `nearest`.
 */
export function meshNearest(accel: MeshAccel, o: Vector3, d: Vector3, tMax: number): boolean {
  setWalkRay(o, d, tMax);
  let distance = Infinity;
  let face = -1;
  for (const root of accel.roots) {
    if (!nodeMeets(root.float32, 0)) continue;
    nearestUnder(root, accel, 0);
    if (found.distance < distance) {
      distance = found.distance;
      face = found.face;
    }
  }
  nearest.distance = distance;
  nearest.face = face;
  return distance !== Infinity;
}

/** The last `meshNearest` hit: its distance along the unit direction and its triangle (BVH order). */
export const nearest = { distance: Infinity, face: -1 };

/** What a subtree's search found: the distance (Infinity: nothing), the triangle and the hit's t. */
const found = { distance: Infinity, face: -1, parameter: 0 };

function nearestUnder(root: PackedRoot, accel: MeshAccel, node: number): void {
  const { float32, uint32, uint16 } = root;
  if (isLeaf(uint16, node)) {
    const offset = uint32[node + 6];
    const end = offset + uint16[node * 2 + 14];
    found.distance = Infinity;
    for (let triangle = offset; triangle < end; triangle++) {
      if (meetsTriangle(accel, triangle) && ray.hitDistance < found.distance) {
        found.distance = ray.hitDistance;
        found.face = triangle;
        found.parameter = ray.hitParameter;
      }
    }
    return;
  }
  const axis = uint32[node + 7];
  const leftToRight = (axis === 0 ? ray.dx : axis === 1 ? ray.dy : ray.dz) >= 0;
  const left = node + UINT32_PER_NODE;
  const right = node + uint32[node + 6] * UINT32_PER_NODE;
  const first = leftToRight ? left : right;
  const second = leftToRight ? right : left;
  if (nodeMeets(float32, first)) nearestUnder(root, accel, first);
  else found.distance = Infinity;
  if (found.distance === Infinity) {
    if (nodeMeets(float32, second)) nearestUnder(root, accel, second);
    return;
  }
  // The first child's hit point along the split axis (three.js's Ray.at), against the second box's near side.
  const point = axis === 0 ? ray.ox + ray.dx * found.parameter : axis === 1 ? ray.oy + ray.dy * found.parameter : ray.oz + ray.dz * found.parameter;
  if (leftToRight ? point <= float32[second + axis] : point >= float32[second + axis + 3]) return;
  if (!nodeMeets(float32, second)) return;
  const { distance, face, parameter } = found;
  nearestUnder(root, accel, second);
  // Of equal distances the first child's hit is kept.
  if (!(found.distance < distance)) {
    found.distance = distance;
    found.face = face;
    found.parameter = parameter;
  }
}
