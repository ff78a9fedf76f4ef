import type { Vector3 } from 'three';
import type { Ray } from '../ray.ts';
import type { MeshAccel } from './mesh-accel.ts';
import { isLeaf, nodeMeets, type PackedRoot, ray, setUnitRay, triangleDistance, UINT32_PER_NODE } from './mesh-walk.ts';

/**
 * Any-hit for shadow rays: does o + t·d (the world ray `limit` in the model's space, where t
 * means the same) meet the model for some t in (0, limit.far)? Walks the model's BVH
 * (mesh-walk.ts) and stops at the first hit; a shadow ray is blocked exactly when
 * `intersectMesh` would find a hit, so the image does not change by a bit.
 */
export function meshOccludes(accel: MeshAccel, o: Vector3, d: Vector3, limit: Ray): boolean {
  const tMax = limit.far;
  const scale = setUnitRay(o, d);
  const far = tMax * scale;
  for (const root of accel.roots) {
    if (rootOccludes(root, accel, far, scale, tMax)) return true;
  }
  return false;
}

/** Nodes waiting to be visited (uint32 offsets); three-mesh-bvh's trees are at most 40 deep. */
const stack = new Uint32Array(256);

function rootOccludes(root: PackedRoot, accel: MeshAccel, far: number, scale: number, tMax: number): boolean {
  const { float32, uint32, uint16 } = root;
  const ix = 1 / ray.dx;
  const iy = 1 / ray.dy;
  const iz = 1 / ray.dz;
  let size = 0;
  if (nodeMeets(float32, 0, ix, iy, iz, far)) stack[size++] = 0;
  while (size > 0) {
    const node = stack[--size];
    if (isLeaf(uint16, node)) {
      const offset = uint32[node + 6];
      const end = offset + uint16[node * 2 + 14];
      for (let triangle = offset; triangle < end; triangle++) {
        // A hit at t in (0, tMax) of the unscaled ray, as intersectMesh checks its nearest one.
        const tWorld = triangleDistance(accel, triangle, far) / scale;
        if (tWorld > 0 && tWorld < tMax) return true;
      }
      continue;
    }
    const left = node + UINT32_PER_NODE;
    const right = node + uint32[node + 6] * UINT32_PER_NODE;
    if (nodeMeets(float32, right, ix, iy, iz, far)) stack[size++] = right;
    if (nodeMeets(float32, left, ix, iy, iz, far)) stack[size++] = left;
  }
  return false;
}
