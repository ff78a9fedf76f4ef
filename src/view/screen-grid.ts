import { Matrix4, type Quaternion, Vector3 } from 'three';
import { DEFAULT_SEED } from '../render/render-job.ts';
import type { Camera, SamplePattern } from '../scene/scene.ts';
import type { CameraRays } from '../tracer/camera-rays.ts';
import { samplePosition } from '../tracer/supersampling.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';

/**
 * The drawn screen of the ray tracer's camera, in the camera rig's local frame: x right,
 * y up, the eye at the origin looking down −z, the screen in the plane z = −distance.
 * It is the image plane of CameraRays moved out to `screenDistance`, so the line from the
 * eye through a cell's centre is exactly that pixel's primary ray.
 */
export interface ScreenGrid {
  columns: number;
  rows: number;
  distance: number;
  /** Half the screen's width and height in metres. */
  halfWidth: number;
  halfHeight: number;
}

/** The screen of `camera`: the vertical fov fixes its height; columns/rows its aspect (square cells). */
export function screenGrid(camera: Camera): ScreenGrid {
  const [columns, rows] = camera.pixels;
  const distance = camera.screenDistance;
  const halfHeight = distance * Math.tan((camera.fov * RADIANS_PER_DEGREE) / 2);
  return { columns, rows, distance, halfHeight, halfWidth: (halfHeight * columns) / rows };
}

/**
 * The local point of image position (px, py), measured in pixels from the screen's top-left
 * corner (y down, as the tracer counts rows): the inverse of CameraRays.direction's mapping.
 */
export function screenPoint(grid: ScreenGrid, px: number, py: number, out: Vector3): Vector3 {
  return out.set(((px / grid.columns) * 2 - 1) * grid.halfWidth, (1 - (py / grid.rows) * 2) * grid.halfHeight, -grid.distance);
}

/** The centre of pixel (x, y) on the screen, in the rig's frame. */
export function cellCenter(grid: ScreenGrid, x: number, y: number, out: Vector3): Vector3 {
  return screenPoint(grid, x + 0.5, y + 0.5, out);
}

/**
 * The pixel under texture coordinates (u, v) of the screen quad (v up, as three.js's
 * PlaneGeometry has it), or null off the screen. Edges belong to the cell right/below them,
 * except the far edges, which belong to the last cell.
 */
export function cellAtUv(u: number, v: number, columns: number, rows: number): [number, number] | null {
  if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) return null;
  const x = Math.min(columns - 1, Math.floor(u * columns));
  const y = Math.min(rows - 1, Math.floor((1 - v) * rows));
  return [x, y];
}

/**
 * The rotation that turns the rig's local axes into the camera's (x → right, y → up,
 * −z → forward), so local points map to world points like the tracer's image plane.
 */
export function cameraRigQuaternion(rays: CameraRays, out: Quaternion): Quaternion {
  basis.makeBasis(rays.right, rays.up, back.copy(rays.forward).negate());
  return out.setFromRotationMatrix(basis);
}

const basis = new Matrix4();
const back = new Vector3();

/**
 * The s×s sample points of every pixel, as local xyz triples in `out` (pixel by pixel, row
 * by row; `columns·rows·s²` points): exactly where the tracer's samplePosition puts them,
 * with the seed the screen's rays are traced with, so jittered dots sit under their rays.
 */
export function samplePoints(grid: ScreenGrid, s: number, pattern: SamplePattern, out: Float32Array): Float32Array {
  const perPixel = s * s;
  let offset = 0;
  for (let y = 0; y < grid.rows; y++) {
    for (let x = 0; x < grid.columns; x++) {
      for (let k = 0; k < perPixel; k++) {
        samplePosition(pattern, s, k, x, y, DEFAULT_SEED, position);
        screenPoint(grid, x + position[0], y + position[1], point).toArray(out, offset);
        offset += 3;
      }
    }
  }
  return out;
}

const position: [number, number] = [0, 0];
const point = new Vector3();
