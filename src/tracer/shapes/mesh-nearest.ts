import type { Vector3 } from 'three';
import type { MeshAccel } from './mesh-accel.ts';
import { isLeaf, lastHitParameter, nodeMeets, type PackedRoot, ray, setUnitRay, triangleDistance, UINT32_PER_NODE } from './mesh-walk.ts';

/**
 * The nearest hit of o + t·d on the model, as three-mesh-bvh's `raycastFirst` (DoubleSide,
 * near 0) finds it, without its allocations (mesh-walk.ts): the same walk, child for child,
 * so the same triangle wins, ties included. At an inner node the child on the ray's side of
 * the split axis goes first, and the other is skipped when the first one's hit lies before
 * the other's box along that axis; a leaf keeps its first nearest triangle; of two children's
 * hits at the same distance the first child's, of two roots' the first root's.
 * @returns the distance along the unit direction (Infinity: no hit nearer than `far`); the
 *   triangle is in `nearestFace`
 */
export function meshNearest(accel: MeshAccel, o: Vector3, d: Vector3, far: number): number {
  setUnitRay(o, d);
  ix = 1 / ray.dx;
  iy = 1 / ray.dy;
  iz = 1 / ray.dz;
  let best = Infinity;
  let bestFace = -1;
  for (const root of accel.roots) {
    if (!nodeMeets(root.float32, 0, ix, iy, iz, far)) continue;
    const distance = nearestUnder(root, accel, 0, far);
    if (distance < best) {
      best = distance;
      bestFace = found.face;
    }
  }
  nearestFace = bestFace;
  return best;
}

/** The triangle (BVH order) of the last `meshNearest` hit. */
export let nearestFace = -1;

/** The ray's reciprocal direction, set once per ray for every box test. */
let ix = 0;
let iy = 0;
let iz = 0;

/** What a subtree's search found besides its distance: the triangle and the hit's ray parameter. */
const found = { face: -1, parameter: 0 };

function nearestUnder(root: PackedRoot, accel: MeshAccel, node: number, far: number): number {
  const { float32, uint32, uint16 } = root;
  if (isLeaf(uint16, node)) {
    const offset = uint32[node + 6];
    const end = offset + uint16[node * 2 + 14];
    let best = Infinity;
    for (let triangle = offset; triangle < end; triangle++) {
      const distance = triangleDistance(accel, triangle, far);
      if (distance < best) {
        best = distance;
        found.face = triangle;
        found.parameter = lastHitParameter;
      }
    }
    return best;
  }
  const axis = uint32[node + 7];
  const direction = axis === 0 ? ray.dx : axis === 1 ? ray.dy : ray.dz;
  const leftToRight = direction >= 0;
  const left = node + UINT32_PER_NODE;
  const right = node + uint32[node + 6] * UINT32_PER_NODE;
  const first = leftToRight ? left : right;
  const second = leftToRight ? right : left;
  const firstDistance = nodeMeets(float32, first, ix, iy, iz, far) ? nearestUnder(root, accel, first, far) : Infinity;
  const firstFace = found.face;
  const firstParameter = found.parameter;
  if (firstDistance !== Infinity) {
    // The hit point along the split axis (three.js's Ray.at), against the second box's near side.
    const point = (axis === 0 ? ray.ox : axis === 1 ? ray.oy : ray.oz) + direction * firstParameter;
    if (leftToRight ? point <= float32[second + axis] : point >= float32[second + axis + 3]) return restore(firstDistance, firstFace, firstParameter);
  }
  const secondDistance = nodeMeets(float32, second, ix, iy, iz, far) ? nearestUnder(root, accel, second, far) : Infinity;
  if (firstDistance !== Infinity && !(secondDistance < firstDistance)) return restore(firstDistance, firstFace, firstParameter);
  return secondDistance;
}

/** Puts a subtree's result back in `found` after a later search overwrote it. */
function restore(distance: number, face: number, parameter: number): number {
  found.face = face;
  found.parameter = parameter;
  return distance;
}
