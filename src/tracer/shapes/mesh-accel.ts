import { Box3, BufferAttribute, BufferGeometry, Vector3 } from 'three';
import { MeshBVH, SAH, type SerializedBVH } from 'three-mesh-bvh';
import type { MeshData, PrebuiltBvh } from '../../scene/mesh-data.ts';
import type { Hit } from '../hit.ts';
import { MESH_BVH_BUILD } from './mesh-bvh-build.ts';
import { meshNearest, nearest } from './mesh-nearest.ts';
import { packedRoot, type PackedRoot, ray } from './mesh-walk.ts';
import { FOUND, REACH, type UnitSpan } from './unit-span.ts';

/** A model's BVH, built once per model and shared by every object that uses it. */
export interface MeshAccel {
  bvh: MeshBVH;
  /** The triangle indices in the BVH's (reordered) order. */
  index: ArrayLike<number>;
  positions: Float32Array;
  normals: Float32Array | null;
  bounds: Box3;
  /** The BVH's packed node buffers, which the tracer's rays walk directly (mesh-walk.ts). */
  roots: PackedRoot[];
}

// Built BVHs by model; a worker keeps them across renders, as models never change.
const accelCache = new WeakMap<MeshData, MeshAccel>();

/** Whether the model's BVH is built already (so meshAccel returns at once). */
export function hasMeshAccel(mesh: MeshData): boolean {
  return accelCache.has(mesh);
}

/**
 * Builds (or reuses) the BVH of a model, or deserializes the one it comes with (mesh.bvh).
 * The geometry gets positions only: three-mesh-bvh allocates a normal, uv and barycentre
 * object per candidate hit for every attribute it finds, so normals are interpolated here
 * instead, once, for the nearest hit.
 */
export function meshAccel(mesh: MeshData): MeshAccel {
  let accel = accelCache.get(mesh);
  if (!accel) {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(mesh.positions, 3));
    let bvh: MeshBVH;
    if (mesh.bvh) {
      geometry.setIndex(new BufferAttribute(mesh.bvh.index, 1));
      // `version` is missing from three-mesh-bvh's typings but read by deserialize: without
      // it the buffers are taken for the old format and rewritten.
      const { version, roots, index } = mesh.bvh;
      bvh = MeshBVH.deserialize({ version, roots, index, indirectBuffer: null } as SerializedBVH, geometry, { setIndex: false });
    } else {
      geometry.setIndex(new BufferAttribute(mesh.indices.slice(), 1));
      bvh = new MeshBVH(geometry, { strategy: { SAH }[MESH_BVH_BUILD.strategy], targetLeafSize: MESH_BVH_BUILD.targetLeafSize });
    }
    geometry.computeBoundingBox();
    const roots = MeshBVH.serialize(bvh, { cloneBuffers: false }).roots.map(packedRoot);
    accel = { bvh, index: geometry.index!.array, positions: mesh.positions, normals: mesh.normals, bounds: geometry.boundingBox!, roots };
    accelCache.set(mesh, accel);
  }
  return accel;
}

/** The model's BVH (built now if it was not yet), copied out so that it can be stored and sent. */
export function prebuiltBvh(mesh: MeshData): PrebuiltBvh {
  const { bvh } = meshAccel(mesh);
  const serialized = MeshBVH.serialize(bvh, { cloneBuffers: false }) as SerializedBVH & { version: number };
  return { version: serialized.version, roots: serialized.roots.map((root) => root.slice(0)), index: Uint32Array.from(serialized.index!) };
}

/**
 * Whether o + t·d meets the model for a t in (0, span[REACH]): the nearest such t goes to
 * span[FOUND] (unit-span.ts) and its triangle to `hit.face`.
 */
export function intersectMesh(accel: MeshAccel, o: Vector3, d: Vector3, hit: Hit, span: UnitSpan): boolean {
  const tMax = span[REACH];
  if (!meshNearest(accel, o, d, tMax)) return false;
  // meshNearest measures distance along a unit direction: back to the ray as given (|d| is the walk's scale).
  const t = nearest.distance / ray.scale;
  if (!(t > 0 && t < tMax)) return false;
  hit.face = nearest.face;
  span[FOUND] = t;
  return true;
}

const a = new Vector3();
const b = new Vector3();
const c = new Vector3();
const barycentric = new Vector3();
const edge1 = new Vector3();
const edge2 = new Vector3();

/** Outward geometric normal of the hit triangle, and the smooth shading normal when the model has vertex normals. */
export function meshNormals(accel: MeshAccel, hit: Hit, geometric: Vector3, shading: Vector3): void {
  const { index, positions, normals } = accel;
  const ia = index[hit.face * 3];
  const ib = index[hit.face * 3 + 1];
  const ic = index[hit.face * 3 + 2];
  a.fromArray(positions, ia * 3);
  b.fromArray(positions, ib * 3);
  c.fromArray(positions, ic * 3);
  geometric.crossVectors(edge1.subVectors(b, a), edge2.subVectors(c, a));
  if (!normals) {
    shading.copy(geometric);
    return;
  }
  // Smooth shading: the vertex normals weighted by the hit's barycentric coordinates.
  barycentricOf(hit.local, a, b, c, barycentric);
  shading
    .fromArray(normals, ia * 3)
    .multiplyScalar(barycentric.x)
    .addScaledVector(a.fromArray(normals, ib * 3), barycentric.y)
    .addScaledVector(b.fromArray(normals, ic * 3), barycentric.z);
}

const v0 = new Vector3();
const v1 = new Vector3();
const v2 = new Vector3();

/** Barycentric coordinates of p in triangle abc (Ericson, Real-Time Collision Detection §3.4). */
function barycentricOf(p: Vector3, pa: Vector3, pb: Vector3, pc: Vector3, out: Vector3): Vector3 {
  v0.subVectors(pb, pa);
  v1.subVectors(pc, pa);
  v2.subVectors(p, pa);
  const d00 = v0.dot(v0);
  const d01 = v0.dot(v1);
  const d11 = v1.dot(v1);
  const d20 = v2.dot(v0);
  const d21 = v2.dot(v1);
  const denom = d00 * d11 - d01 * d01;
  if (denom === 0) return out.set(1, 0, 0);
  const v = (d11 * d20 - d01 * d21) / denom;
  const w = (d00 * d21 - d01 * d20) / denom;
  return out.set(1 - v - w, v, w);
}
