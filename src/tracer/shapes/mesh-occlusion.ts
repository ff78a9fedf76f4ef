import type { Vector3 } from 'three';
import type { Ray } from '../ray.ts';
import type { MeshAccel } from './mesh-accel.ts';
import { isLeaf, meetsTriangle, nodeMeets, ray, setWalkRay, UINT32_PER_NODE } from './mesh-walk.ts';

/** Nodes waiting to be visited (uint32 offsets); three-mesh-bvh's trees are at most 40 deep. */
const stack = new Uint32Array(256);

/**
 * Any-hit for shadow rays: does o + t·d (the world ray `limit` in the model's space, where t
 * means the same) meet the model for some t in (0, limit.far)? Walks the model's BVH
 * (mesh-walk.ts) and stops at the first hit; a shadow ray is blocked exactly when
 * `intersectMesh` would find a hit, so the image does not change by a bit.
 */
export function meshOccludes(accel: MeshAccel, o: Vector3, d: Vector3, limit: Ray): boolean {
  const tMax = limit.far;
  setWalkRay(o, d, tMax);
  for (const { float32, uint32, uint16 } of accel.roots) {
    let size = 0;
    if (nodeMeets(float32, 0)) stack[size++] = 0;
    while (size > 0) {
      const node = stack[--size];
      if (isLeaf(uint16, node)) {
        const offset = uint32[node + 6];
        const end = offset + uint16[node * 2 + 14];
        for (let triangle = offset; triangle < end; triangle++) {
          if (!meetsTriangle(accel, triangle)) continue;
          // A hit at t in (0, tMax) of the ray as given, as intersectMesh checks its nearest one.
          const t = ray.hitDistance / ray.scale;
          if (t > 0 && t < tMax) return true;
        }
        continue;
      }
      const left = node + UINT32_PER_NODE;
      const right = node + uint32[node + 6] * UINT32_PER_NODE;
      if (nodeMeets(float32, right)) stack[size++] = right;
      if (nodeMeets(float32, left)) stack[size++] = left;
    }
  }
  return false;
}
