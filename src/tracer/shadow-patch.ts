import { Box3, type Vector3 } from 'three';
import type { Intersectable } from './intersectable.ts';
import type { TracerLight } from './lights.ts';
import { listOverlapping, type ObjectBvh } from './object-bvh.ts';
import { RayCone } from './ray-cone.ts';

/** √3: a cube of half-side h lies within h·√3 of its centre. */
const CUBE_RADIUS = Math.sqrt(3);

/**
 * The shadow candidates of one light for a patch of hit points: a cube of half-side `half`
 * around the hit that started it. Neighbouring pixels hit neighbouring points, and every
 * shadow ray from any point of the cube toward the light stays inside the box spanned by the
 * cube and the light, and inside the light's pyramid from the cube's centre widened by the
 * cube's radius (a segment from p to a light point q lies within |p − p₀| of the segment from
 * p₀ to q, and a convex solid's ε-neighbourhood lies inside its planes each moved out by ε).
 * So the objects found for the patch include every object that can block a shadow ray from
 * any of its points: the list is gathered once per patch instead of once per hit, and each
 * hit tests the same shadow rays against a few more objects at most, with the same result.
 */
export class ShadowPatch {
  /** The objects found (the first `count`; -1: too many to list). */
  readonly list: Intersectable[] = [];
  count = 0;
  private x = 0;
  private y = 0;
  private z = 0;
  private half = 0;
  private filled = false;
  private readonly reach = new Box3();
  private readonly cone = new RayCone();

  /** Whether `point` lies in this patch's cube. */
  covers(point: Vector3): boolean {
    const half = this.half;
    return this.filled && Math.abs(point.x - this.x) <= half && Math.abs(point.y - this.y) <= half && Math.abs(point.z - this.z) <= half;
  }

  /**
   * Starts the patch around `point`: lists the objects of `occluders` that overlap the box of
   * the cube and `light`, and (an area light) its widened pyramid; `margin` covers the shadow
   * rays' ε offsets, `limit` is how many are worth listing; `from` is the object `point`
   * lies on, where the BVH walks start (walk-starts.ts).
   */
  fill(
    point: Vector3,
    half: number,
    light: TracerLight,
    occluders: readonly ObjectBvh[],
    margin: number,
    limit: number,
    from: Intersectable | null = null,
  ): void {
    this.x = point.x;
    this.y = point.y;
    this.z = point.z;
    this.half = half;
    this.filled = true;
    const reach = this.reach;
    reach.min.set(point.x - half, point.y - half, point.z - half);
    reach.max.set(point.x + half, point.y + half, point.z + half);
    reach.union(light.extent);
    const cone = light.type === 'area' ? this.cone.toLight(point, light, margin + half * CUBE_RADIUS) : null;
    this.count = listOverlapping(occluders, reach, this.list, limit, cone, from);
  }
}

/**
 * Two patches of one light at one recursion depth, the one used last tried first. With
 * s × s supersampling a pixel's samples alternate between s rows of hits, and on a floor seen
 * at a grazing angle half a pixel down moves a hit further in depth than a patch is wide: one
 * patch was filled again at nearly every change of row. With two, the rows keep one each
 * (the reference scene fills 24 % fewer; four or six, replaced in turn, saved under 2 % more).
 */
export class ShadowPatchPair {
  private readonly patches = [new ShadowPatch(), new ShadowPatch()];
  private used = 0;

  /**
   * The patch whose cube covers `point`; else the one used less recently, filled around
   * `point` (ShadowPatch.fill's arguments).
   */
  listFor(
    point: Vector3,
    half: number,
    light: TracerLight,
    occluders: readonly ObjectBvh[],
    margin: number,
    limit: number,
    from: Intersectable | null = null,
  ): ShadowPatch {
    const last = this.patches[this.used];
    if (last.covers(point)) return last;
    this.used ^= 1;
    const other = this.patches[this.used];
    if (!other.covers(point)) other.fill(point, half, light, occluders, margin, limit, from);
    return other;
  }
}
