import type { Vector3 } from 'three';
import type { Intersectable } from './intersectable.ts';
import type { Ray } from './ray.ts';

/** Cells per side of a face: about four per object along a side of a square grid of objects, at most 64 (6 × 64² cells). */
const MAX_CELLS_PER_SIDE = 64;
/** How far past its footprint's rounded edges an object is listed, in cells: covers the rounding of both projections. */
const CELL_MARGIN = 1e-6;

/**
 * The light buffer of a point or spot light (Haines & Greenberg, "The Light Buffer: A Shadow
 * Testing Accelerator", 1986): a cube of directions around the light, each face cut into
 * n × n cells, each cell listing the objects seen from the light through it. Whatever blocks
 * a shadow ray toward the light lies in the direction from the light back along the ray, so
 * the ray tests the objects of one cell (a few) instead of walking the object BVH (about ten
 * boxes on the 256-object benchmark grid).
 *
 * Conservative, so the image stays the same: each object's box is widened by `margin`, which
 * covers the shadow ray's start ε off the surface (the ray then runs within ε of the segment
 * from the hit to the light, whose every point lies exactly in the looked-up direction), and
 * each footprint by a millionth of a cell for rounding. Objects are listed in the order given
 * (cheap shapes before meshes).
 */
export class LightBuffer {
  /** The cells' objects, cell after cell: cell c's are objects[starts[c]] … objects[starts[c + 1] − 1]. */
  readonly objects: Intersectable[] = [];
  readonly starts: Int32Array;
  private readonly cellsPerSide: number;
  private readonly x: number;
  private readonly y: number;
  private readonly z: number;

  constructor(light: Vector3, shapes: readonly Intersectable[], margin: number) {
    this.x = light.x;
    this.y = light.y;
    this.z = light.z;
    const n = Math.min(MAX_CELLS_PER_SIDE, 4 * Math.ceil(Math.sqrt(Math.max(1, shapes.length))));
    this.cellsPerSide = n;
    const counts = new Int32Array(6 * n * n + 1);
    const footprints = shapes.map((shape) => this.footprint(shape, margin));
    for (const rectangles of footprints) forEachCell(rectangles, n, (cell) => counts[cell]++);
    // Prefix sums: starts[c] is where cell c's list begins.
    this.starts = new Int32Array(6 * n * n + 1);
    for (let c = 0; c < 6 * n * n; c++) this.starts[c + 1] = this.starts[c] + counts[c];
    const filled = this.starts.slice(0, 6 * n * n);
    footprints.forEach((rectangles, i) => forEachCell(rectangles, n, (cell) => (this.objects[filled[cell]++] = shapes[i])));
  }

  /**
   * The first object of the cell the ray comes from that blocks it (Intersectable.occludes),
   * or null; `skip` is not tested. The ray must end at the light (ray.far short of it).
   */
  firstBlocker(ray: Ray, skip: Intersectable | null): Intersectable | null {
    const d = ray.direction;
    const cell = this.cell(-d.x, -d.y, -d.z);
    const { objects, starts } = this;
    for (let i = starts[cell], end = starts[cell + 1]; i < end; i++) {
      const object = objects[i];
      if (object !== skip && object.occludes(ray)) return object;
    }
    return null;
  }

  /**
   * The cell holding the direction (dx, dy, dz) from the light (not necessarily unit): the
   * face of its largest component, and the other two components over that one, each in −1..1.
   */
  cell(dx: number, dy: number, dz: number): number {
    const ax = Math.abs(dx);
    const ay = Math.abs(dy);
    const az = Math.abs(dz);
    let face: number;
    let u: number;
    let v: number;
    if (ax >= ay && ax >= az) {
      face = dx < 0 ? 1 : 0;
      u = dy / ax;
      v = dz / ax;
    } else if (ay >= az) {
      face = dy < 0 ? 3 : 2;
      u = dz / ay;
      v = dx / ay;
    } else {
      face = dz < 0 ? 5 : 4;
      u = dx / az;
      v = dy / az;
    }
    const n = this.cellsPerSide;
    const i = Math.min(n - 1, Math.max(0, Math.floor((u + 1) * 0.5 * n)));
    const j = Math.min(n - 1, Math.max(0, Math.floor((v + 1) * 0.5 * n)));
    return (face * n + j) * n + i;
  }

  /**
   * Per face (+x, −x, +y, −y, +z, −z), the rectangle of cells (i0, j0, i1, j1) through which
   * the box widened by `margin` is seen from the light, or null where it is not seen at all.
   *
   * A face sees the directions whose component along its axis, w, is at least the other two
   * in size. A box at max-norm distance D from the light has no such point with w < D, so
   * only its part with w ≥ D/2 matters: there w > 0 and the projection (b/w, c/w) of that
   * part lies within the span of its eight corners' projections. A box holding the light
   * (D = 0) is seen through every cell.
   */
  private footprint(shape: Intersectable, margin: number): (number[] | null)[] {
    const { min, max } = shape.worldBounds;
    const n = this.cellsPerSide;
    // The widened box relative to the light, per axis.
    const lo = [min.x - margin - this.x, min.y - margin - this.y, min.z - margin - this.z];
    const hi = [max.x + margin - this.x, max.y + margin - this.y, max.z + margin - this.z];
    const everyCell = Array(6).fill([0, 0, n - 1, n - 1]);
    if (![...lo, ...hi].every(Number.isFinite)) return everyCell;
    const distance = Math.max(...[0, 1, 2].map((k) => Math.max(lo[k], -hi[k], 0)));
    if (distance === 0) return everyCell;
    // The cell of coordinate t (−1..1), moved by `margin` cells first.
    const toCell = (t: number, margin: number) => Math.min(n - 1, Math.max(0, Math.floor((t + 1) * 0.5 * n + margin)));
    return [0, 1, 2, 3, 4, 5].map((face) => {
      const axis = face >> 1;
      // The face's (u, v) axes, as in cell(): y, z for x; z, x for y; x, y for z.
      const [ua, va] = [(axis + 1) % 3, (axis + 2) % 3];
      const near = Math.max(face & 1 ? -hi[axis] : lo[axis], distance / 2);
      const far = face & 1 ? -lo[axis] : hi[axis];
      if (far < near) return null;
      const us = [lo[ua] / near, hi[ua] / near, lo[ua] / far, hi[ua] / far];
      const vs = [lo[va] / near, hi[va] / near, lo[va] / far, hi[va] / far];
      return [
        toCell(Math.min(...us), -CELL_MARGIN),
        toCell(Math.min(...vs), -CELL_MARGIN),
        toCell(Math.max(...us), CELL_MARGIN),
        toCell(Math.max(...vs), CELL_MARGIN),
      ];
    });
  }
}

function forEachCell(rectangles: readonly (number[] | null)[], n: number, visit: (cell: number) => void): void {
  rectangles.forEach((rectangle, face) => {
    if (!rectangle) return;
    const [i0, j0, i1, j1] = rectangle;
    for (let j = j0; j <= j1; j++) for (let i = i0; i <= i1; i++) visit((face * n + j) * n + i);
  });
}
