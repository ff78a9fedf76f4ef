import type { Vector3 } from 'three';
import type { TracerLight } from './lights.ts';

/**
 * A cone of rays from one apex through a quadrilateral, as planes that cull boxes: what
 * cannot meet any of its rays. Two kinds (the ray tracer's two coherent bundles):
 *
 * - `toLight`: every shadow ray from a hit point to an area light, the pyramid with its apex
 *   at the point and the light's rectangle as its base (every sample point lies in the
 *   rectangle position ± halfWidth ± halfDepth, lights.ts; a disc's points lie in its
 *   square). Its side planes and its base plane cull the shadow candidates far tighter than
 *   the box around point and light does: above a crowd of objects, that box overlaps dozens
 *   of them while the pyramid's narrow end near the point meets a few (the 256-object
 *   benchmark grid).
 * - `throughQuad`: the camera's rays through a rectangle of the image (a tile), with no base
 *   (primary-candidates.ts).
 *
 * Conservative by `margin`: a box is excluded only when it lies wholly outside one plane by
 * more than the margin, which covers a shadow ray's offset origin (ε along the normal) and
 * its end (ε short of the sample), so no possible blocker is ever dropped and the image stays
 * the same. A plane that degenerates (the point in the light's plane) is left out, which only
 * makes the test looser. Culling a box by separating planes: Assarsson & Möller, "Optimized
 * View Frustum Culling Algorithms for Bounding Boxes" (2000), the n-vertex test.
 */
export class RayCone {
  /** Per plane: normal x, y, z (pointing out, not unit length) and offset d, outside where n·x > d. */
  private readonly planes = new Float64Array(5 * 4);
  /** Per plane: where in a box's six numbers its n-vertex's x, y and z are (min or max per axis). */
  private readonly corner = new Uint8Array(5 * 3);
  private planeCount = 0;
  /** The light's four corners, x, y, z each (scratch: toLight() runs for every hit and area light). */
  private readonly corners = new Float64Array(4 * 3);

  /** The cone from `point` over `light` (an area light), widened by `margin`. */
  toLight(point: Vector3, light: TracerLight, margin: number): this {
    const { position: c, halfWidth: w, halfDepth: h } = light;
    // The corners in order around the rectangle: c − w − h, c + w − h, c + w + h, c − w + h.
    const corners = this.corners;
    for (let i = 0; i < 4; i++) {
      const u = i === 1 || i === 2 ? 1 : -1;
      const v = i < 2 ? -1 : 1;
      corners[i * 3] = c.x + u * w.x + v * h.x;
      corners[i * 3 + 1] = c.y + u * w.y + v * h.y;
      corners[i * 3 + 2] = c.z + u * w.z + v * h.z;
    }
    // A point inside the pyramid, to orient the planes outward.
    const mx = (point.x + c.x) / 2;
    const my = (point.y + c.y) / 2;
    const mz = (point.z + c.z) / 2;
    this.setSides(point, corners, mx, my, mz, margin);
    // The base: the light's own plane, normal w × h.
    this.addPlane(w.y * h.z - w.z * h.y, w.z * h.x - w.x * h.z, w.x * h.y - w.y * h.x, c.x, c.y, c.z, mx, my, mz, margin);
    return this;
  }

  /**
   * The rays from `apex` through the quadrilateral `corners` (x, y, z of four points, in
   * order around it) and on past it, widened by `margin`.
   */
  throughQuad(apex: Vector3, corners: Float64Array, margin: number): this {
    // The quadrilateral's centre is inside the cone.
    let mx = 0,
      my = 0,
      mz = 0;
    for (let i = 0; i < 4; i++) {
      mx += corners[i * 3] / 4;
      my += corners[i * 3 + 1] / 4;
      mz += corners[i * 3 + 2] / 4;
    }
    this.setSides(apex, corners, mx, my, mz, margin);
    return this;
  }

  /** Starts the planes afresh with the four sides from `apex` through the edges of `corners`, oriented away from (mx, my, mz). */
  private setSides(apex: Vector3, corners: Float64Array, mx: number, my: number, mz: number, margin: number): void {
    this.planeCount = 0;
    for (let i = 0; i < 4; i++) {
      const a = i * 3;
      const b = ((i + 1) & 3) * 3;
      const ax = corners[a] - apex.x,
        ay = corners[a + 1] - apex.y,
        az = corners[a + 2] - apex.z;
      const bx = corners[b] - apex.x,
        by = corners[b + 1] - apex.y,
        bz = corners[b + 2] - apex.z;
      this.addPlane(ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx, apex.x, apex.y, apex.z, mx, my, mz, margin);
    }
  }

  /** Whether the box at boxes[at..at+5] (min x, y, z, max x, y, z) lies wholly outside the cone. */
  excludes(boxes: Float64Array, at: number): boolean {
    const { planes: p, corner: c } = this;
    for (let i = 0; i < this.planeCount; i++) {
      const k = i * 4;
      const j = i * 3;
      // n · the box's corner farthest inside the plane (the n-vertex).
      if (p[k] * boxes[at + c[j]] + p[k + 1] * boxes[at + c[j + 1]] + p[k + 2] * boxes[at + c[j + 2]] > p[k + 3]) return true;
    }
    return false;
  }

  /**
   * The plane through (px, py, pz) with normal (nx, ny, nz), turned away from (mx, my, mz) and
   * moved out by `margin`. The normal is not normalised (a square root and three divisions
   * per plane, five planes per hit and area light): the margin is scaled by its L1 length
   * |nx| + |ny| + |nz| instead, which is at least its true length, so the plane only moves
   * out a little further and the test stays conservative.
   */
  private addPlane(nx: number, ny: number, nz: number, px: number, py: number, pz: number, mx: number, my: number, mz: number, margin: number): void {
    const l1Length = Math.abs(nx) + Math.abs(ny) + Math.abs(nz);
    if (!(l1Length > 0)) return;
    const scaledMargin = margin * l1Length;
    let d = nx * px + ny * py + nz * pz;
    const inner = nx * mx + ny * my + nz * mz - d;
    // The inner point on the plane: the pyramid is flat there, this plane cannot orient.
    if (!(Math.abs(inner) > scaledMargin)) return;
    if (inner > 0) {
      nx = -nx;
      ny = -ny;
      nz = -nz;
      d = -d;
    }
    const i = this.planeCount++;
    this.corner[i * 3] = nx > 0 ? 0 : 3;
    this.corner[i * 3 + 1] = ny > 0 ? 1 : 4;
    this.corner[i * 3 + 2] = nz > 0 ? 2 : 5;
    const at = i * 4;
    this.planes[at] = nx;
    this.planes[at + 1] = ny;
    this.planes[at + 2] = nz;
    this.planes[at + 3] = d + scaledMargin;
  }
}
