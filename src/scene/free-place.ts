import type { SceneObject, Vec3 } from './scene.ts';

/** Metres between the grid points a new object may stand on. */
const STEP = 0.5;
/** How far from where the camera looks a new object may be put (metres). */
const REACH = 6;
/** Room left between a new object and its neighbours (metres). */
const GAP = 0.1;

/**
 * How far an object reaches across the floor from its centre: every unit shape (and model)
 * fits in a box of ±0.5 before scaling (a prism's corners reach 0.58), so its footprint fits
 * in a circle of half the diagonal of its larger side, whichever way it is turned about y.
 */
export function footprintRadius(object: Pick<SceneObject, 'scale'>): number {
  return 0.58 * Math.SQRT2 * Math.max(Math.abs(object.scale[0]), Math.abs(object.scale[2]));
}

/**
 * Where on the floor (x, z) a new object with footprint `radius` stands free of the
 * objects already there, as near as possible to `centre` (where the camera looks): grid
 * points 0.5 m apart, nearest first. Planes (floors, walls) do not count. When nothing is
 * free within 6 m, the centre itself.
 */
export function freePlace(objects: readonly SceneObject[], radius: number, centre: Vec3): [number, number] {
  const standing = objects.filter((object) => object.shape !== 'plane');
  const free = (x: number, z: number) =>
    standing.every((object) => Math.hypot(x - object.position[0], z - object.position[2]) >= radius + footprintRadius(object) + GAP);
  const [cx, cz] = [Math.round(centre[0] / STEP) * STEP, Math.round(centre[2] / STEP) * STEP];
  const points: [number, number][] = [];
  for (let i = -REACH / STEP; i <= REACH / STEP; i++) for (let j = -REACH / STEP; j <= REACH / STEP; j++) points.push([cx + i * STEP, cz + j * STEP]);
  // Nearest first; at equal distance, the one in front (larger z, towards a camera at +z) and then to the right, so the choice does not depend on the loop's order.
  points.sort(([ax, az], [bx, bz]) => Math.hypot(ax - cx, az - cz) - Math.hypot(bx - cx, bz - cz) || bz - az || bx - ax);
  return points.find(([x, z]) => free(x, z)) ?? [cx, cz];
}
