import type { Vector3 } from 'three';
import type { MeshAccel } from './mesh-accel.ts';

/**
 * What the tracer's own walks of a model's BVH share (mesh-occlusion.ts for shadow rays,
 * mesh-nearest.ts for the nearest hit): three-mesh-bvh's packed node buffers read directly
 * (its node layout: 8 × 32 bits a node, six float32 bounds, then a leaf's triangle offset
 * and count, flagged 0xFFFF, or an inner node's right-child offset in nodes and its split
 * axis; the left child follows its parent), with no allocation per ray or per triangle (its
 * `raycastFirst` allocates 4–5 objects per candidate triangle).
 *
 * The box and triangle tests repeat `raycastFirst`'s arithmetic operation for operation (its
 * `intersectsNodeBounds`, three.js's watertight `Ray.intersectTriangle`, the distance to the
 * hit point), so the walks find exactly what it finds.
 *
 * The ray, its reach and the last hit's numbers live in one shared object (`ray`), not in
 * arguments and return values, as these calls run per node and per triangle: docs/performance.md,
 * "Numbers passed to calls".
 */

/** The node buffers of one BVH root, read through three views as three-mesh-bvh does. */
export interface PackedRoot {
  readonly float32: Float32Array;
  readonly uint32: Uint32Array;
  readonly uint16: Uint16Array;
}

export function packedRoot(buffer: ArrayBuffer): PackedRoot {
  return { float32: new Float32Array(buffer), uint32: new Uint32Array(buffer), uint16: new Uint16Array(buffer) };
}

export const UINT32_PER_NODE = 8;
const IS_LEAF_FLAG = 0xffff;

export function isLeaf(uint16: Uint16Array, node: number): boolean {
  return uint16[node * 2 + 15] === IS_LEAF_FLAG;
}

interface WalkRay {
  /** The origin and the unit direction, in the model's space. */
  ox: number;
  oy: number;
  oz: number;
  dx: number;
  dy: number;
  dz: number;
  /** 1 / the direction, per axis, for the box tests. */
  ix: number;
  iy: number;
  iz: number;
  /** |d| of the ray as given: distances along the unit direction are t·scale. */
  scale: number;
  /** The greatest distance along the unit direction that counts. */
  far: number;
  /** The last hit `meetsTriangle` found: its distance along the unit direction, and its t for three.js's Ray.at. */
  hitDistance: number;
  hitParameter: number;
}

/** The ray being walked (one object, reused). */
export const ray: WalkRay = { ox: 0, oy: 0, oz: 0, dx: 0, dy: 0, dz: 0, ix: 0, iy: 0, iz: 0, scale: 1, far: 0, hitDistance: 0, hitParameter: 0 };

/**
 * Sets `ray` to o + t·d, t < tMax, with d made unit, as three-mesh-bvh measures distance
 * along a unit direction (Vector3.divideScalar multiplies by the reciprocal).
 */
export function setWalkRay(o: Vector3, d: Vector3, tMax: number): void {
  const scale = Math.sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  const inverseScale = 1 / scale;
  ray.ox = o.x;
  ray.oy = o.y;
  ray.oz = o.z;
  ray.dx = d.x * inverseScale;
  ray.dy = d.y * inverseScale;
  ray.dz = d.z * inverseScale;
  ray.ix = 1 / ray.dx;
  ray.iy = 1 / ray.dy;
  ray.iz = 1 / ray.dz;
  ray.scale = scale;
  ray.far = tMax * scale;
}

/** three-mesh-bvh's intersectsNodeBounds with near = 0 and far = ray.far, for node `n`'s box. */
export function nodeMeets(box: Float32Array, n: number): boolean {
  const { ix, iy, iz, far } = ray;
  let tmin: number;
  let tmax: number;
  let tymin: number;
  let tymax: number;
  let tzmin: number;
  let tzmax: number;
  if (ix >= 0) {
    tmin = (box[n] - ray.ox) * ix;
    tmax = (box[n + 3] - ray.ox) * ix;
  } else {
    tmin = (box[n + 3] - ray.ox) * ix;
    tmax = (box[n] - ray.ox) * ix;
  }
  if (iy >= 0) {
    tymin = (box[n + 1] - ray.oy) * iy;
    tymax = (box[n + 4] - ray.oy) * iy;
  } else {
    tymin = (box[n + 4] - ray.oy) * iy;
    tymax = (box[n + 1] - ray.oy) * iy;
  }
  if (tmin > tymax || tymin > tmax) return false;
  if (tymin > tmin || tmin !== tmin) tmin = tymin;
  if (tymax < tmax || tmax !== tmax) tmax = tymax;
  if (iz >= 0) {
    tzmin = (box[n + 2] - ray.oz) * iz;
    tzmax = (box[n + 5] - ray.oz) * iz;
  } else {
    tzmin = (box[n + 5] - ray.oz) * iz;
    tzmax = (box[n + 2] - ray.oz) * iz;
  }
  if (tmin > tzmax || tzmin > tmax) return false;
  if (tzmin > tmin || tmin !== tmin) tmin = tzmin;
  if (tzmax < tmax || tmax !== tmax) tmax = tzmax;
  return tmin <= far && tmax >= 0;
}

/**
 * Whether the ray meets triangle `triangle` (BVH order) no farther than ray.far; the hit's
 * distance from the origin (which may be NaN, which no comparison accepts, as in
 * three-mesh-bvh) and t go into ray.hitDistance and ray.hitParameter. Woop, Benthin & Wald,
 * "Watertight Ray/Triangle Intersection" (JCGT 2013), written as three.js's
 * Ray.intersectTriangle without back-face culling.
 */
export function meetsTriangle(accel: MeshAccel, triangle: number): boolean {
  const { index, positions } = accel;
  const a = index[triangle * 3] * 3;
  const b = index[triangle * 3 + 1] * 3;
  const c = index[triangle * 3 + 2] * 3;
  const { ox, oy, oz, dx, dy, dz } = ray;
  const aox = positions[a] - ox,
    aoy = positions[a + 1] - oy,
    aoz = positions[a + 2] - oz;
  const box = positions[b] - ox,
    boy = positions[b + 1] - oy,
    boz = positions[b + 2] - oz;
  const cox = positions[c] - ox,
    coy = positions[c + 1] - oy,
    coz = positions[c + 2] - oz;
  const adx = Math.abs(dx),
    ady = Math.abs(dy),
    adz = Math.abs(dz);
  let dkx: number, dky: number, dkz: number;
  let akx: number, aky: number, akz: number, bkx: number, bky: number, bkz: number, ckx: number, cky: number, ckz: number;
  if (adx >= ady && adx >= adz) {
    dkz = dx;
    akz = aox;
    bkz = box;
    ckz = cox;
    if (dx >= 0) {
      dkx = dy;
      dky = dz;
      akx = aoy;
      aky = aoz;
      bkx = boy;
      bky = boz;
      ckx = coy;
      cky = coz;
    } else {
      dkx = dz;
      dky = dy;
      akx = aoz;
      aky = aoy;
      bkx = boz;
      bky = boy;
      ckx = coz;
      cky = coy;
    }
  } else if (ady >= adz) {
    dkz = dy;
    akz = aoy;
    bkz = boy;
    ckz = coy;
    if (dy >= 0) {
      dkx = dz;
      dky = dx;
      akx = aoz;
      aky = aox;
      bkx = boz;
      bky = box;
      ckx = coz;
      cky = cox;
    } else {
      dkx = dx;
      dky = dz;
      akx = aox;
      aky = aoz;
      bkx = box;
      bky = boz;
      ckx = cox;
      cky = coz;
    }
  } else {
    dkz = dz;
    akz = aoz;
    bkz = boz;
    ckz = coz;
    if (dz >= 0) {
      dkx = dx;
      dky = dy;
      akx = aox;
      aky = aoy;
      bkx = box;
      bky = boy;
      ckx = cox;
      cky = coy;
    } else {
      dkx = dy;
      dky = dx;
      akx = aoy;
      aky = aox;
      bkx = boy;
      bky = box;
      ckx = coy;
      cky = cox;
    }
  }
  if (dkz === 0) return false;
  const sx = dkx / dkz,
    sy = dky / dkz,
    sz = 1 / dkz;
  const ax = akx - sx * akz,
    ay = aky - sy * akz;
  const bx = bkx - sx * bkz,
    by = bky - sy * bkz;
  const cx = ckx - sx * ckz,
    cy = cky - sy * ckz;
  const u = cx * by - cy * bx;
  const v = ax * cy - ay * cx;
  const w = bx * ay - by * ax;
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
  const det = u + v + w;
  if (det === 0) return false;
  const tScaled = sz * (u * akz + v * bkz + w * ckz);
  if (det > 0 ? tScaled < 0 : tScaled > 0) return false;
  // The hit point o + t·d and its distance from o, as Ray.at and Vector3.distanceTo compute them.
  const t = tScaled / det;
  const ex = ox - (ox + dx * t),
    ey = oy - (oy + dy * t),
    ez = oz - (oz + dz * t);
  const distance = Math.sqrt(ex * ex + ey * ey + ez * ez);
  if (distance > ray.far) return false;
  ray.hitDistance = distance;
  ray.hitParameter = t;
  return true;
}
