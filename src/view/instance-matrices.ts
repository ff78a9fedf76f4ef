/**
 * Where each drawn ray and cone sits: the instance matrices that map a unit ribbon or pyramid
 * (instance-buffers.ts) onto a segment of a SegmentList, and a cone's width along it for picking.
 */
import type { SegmentList } from './ray-visibility.ts';

/** A cone's half-width at `s` metres from its apex: the larger half-side of the light, scaled. */
export function coneRadiusAt(list: SegmentList, i: number, s: number): number {
  const c = list.corners;
  const k = i * 12;
  const halfWidth = Math.hypot(c[k + 3] - c[k], c[k + 4] - c[k + 1], c[k + 5] - c[k + 2]) / 2;
  const halfDepth = Math.hypot(c[k + 9] - c[k], c[k + 10] - c[k + 1], c[k + 11] - c[k + 2]) / 2;
  return (Math.max(halfWidth, halfDepth) * s) / list.length[i];
}

/**
 * Unit cylinder → ray i: column 0 and 1 an orthonormal basis across the ray scaled by its
 * radius, column 2 the direction scaled by its length, column 3 its origin (column-major,
 * as three.js stores matrices). The helper axis is +Y unless the ray is nearly vertical.
 */
export function writeCylinderMatrix(m: Float32Array, at: number, list: SegmentList, i: number): void {
  const o = i * 3;
  const dx = list.direction[o];
  const dy = list.direction[o + 1];
  const dz = list.direction[o + 2];
  const r = list.radius[i];
  const length = list.length[i];
  // x = normalize(helper × d); y = d × x. The square root written out: d is a unit vector, so
  // nothing can overflow, and Math.hypot (varargs, guarded against overflow) was a quarter of
  // a 10k-ray rebuild.
  let xx: number;
  let xy: number;
  let xz: number;
  if (Math.abs(dy) < 0.99) {
    const n = 1 / Math.sqrt(dz * dz + dx * dx);
    xx = dz * n;
    xy = 0;
    xz = -dx * n;
  } else {
    const n = 1 / Math.sqrt(dz * dz + dy * dy);
    xx = 0;
    xy = -dz * n;
    xz = dy * n;
  }
  const yx = dy * xz - dz * xy;
  const yy = dz * xx - dx * xz;
  const yz = dx * xy - dy * xx;
  m[at] = xx * r;
  m[at + 1] = xy * r;
  m[at + 2] = xz * r;
  m[at + 3] = 0;
  m[at + 4] = yx * r;
  m[at + 5] = yy * r;
  m[at + 6] = yz * r;
  m[at + 7] = 0;
  m[at + 8] = dx * length;
  m[at + 9] = dy * length;
  m[at + 10] = dz * length;
  m[at + 11] = 0;
  m[at + 12] = list.origin[o];
  m[at + 13] = list.origin[o + 1];
  m[at + 14] = list.origin[o + 2];
  m[at + 15] = 1;
}

/**
 * Unit pyramid → cone i: apex at the hit point, base (x, y, 1) ↦ centre + x·U + y·V with
 * U, V the light's half-sides from its corners c0..c3 (U = (c1 − c0)/2, V = (c3 − c0)/2).
 */
export function writeConeMatrix(m: Float32Array, at: number, list: SegmentList, i: number): void {
  const c = list.corners;
  const k = i * 12;
  const o = i * 3;
  for (let axis = 0; axis < 3; axis++) {
    const apex = list.origin[o + axis];
    const centre = (c[k + axis] + c[k + 3 + axis] + c[k + 6 + axis] + c[k + 9 + axis]) / 4;
    m[at + axis] = (c[k + 3 + axis] - c[k + axis]) / 2;
    m[at + 4 + axis] = (c[k + 9 + axis] - c[k + axis]) / 2;
    m[at + 8 + axis] = centre - apex;
    m[at + 12 + axis] = apex;
  }
  m[at + 3] = 0;
  m[at + 7] = 0;
  m[at + 11] = 0;
  m[at + 15] = 1;
}
