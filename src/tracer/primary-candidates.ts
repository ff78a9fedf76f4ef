import { Vector3 } from 'three';
import type { Intersectable } from './intersectable.ts';
import type { Ray } from './ray.ts';
import { RayCone } from './ray-cone.ts';
import type { TracerScene } from './tracer-scene.ts';

/**
 * Past this many objects a tile's list is not kept: its rays walk the object BVH, which
 * prunes by the nearest hit so far where a list tests every entry.
 */
const MAX_LISTED = 24;

const corner = new Vector3();

/**
 * The objects that the primary rays of a pinhole camera through one rectangle of the image
 * (a tile) can hit, in the order the object BVH's nearest-hit walk tests them: a tile's rays
 * then test a few objects each instead of walking the BVH from its root (view-frustum
 * culling per tile; Assarsson & Möller 2000 for the box test).
 *
 * The same hit, to the bit, as the walk (ObjectBvh.nearest), ties included. The list holds
 * every object whose box is not wholly outside the cone of the tile's rays, in the walk's
 * order for the direction signs of the tile's centre ray; a ray with other signs (a tile
 * across the image's centre line, say) walks the BVH itself. For a ray with those signs the
 * walk tests a subsequence of the list, in the same order: an object it skips is one whose
 * box, or a node box around it, the ray misses or enters beyond the nearest hit so far, and
 * the object's own box test (the same numbers, inside the node's) then fails in the list
 * too. The cone is widened by a pixel and by ε, far more than rounding moves a ray, so
 * no object a ray can hit is left out.
 */
export class PrimaryCandidates {
  /** The objects (the first `count`); count -1: none listed, rays walk the BVH. */
  readonly list: Intersectable[] = [];
  /** Their world boxes, six numbers each (min x, y, z, max x, y, z): a ray tests each before calling the object. */
  readonly boxes = new Float64Array(MAX_LISTED * 6);
  count = -1;
  /** The direction signs the list's order is for (backwardAxes). */
  private backwardAxes = 0;
  private readonly cone = new RayCone();
  private readonly corners = new Float64Array(12);

  /**
   * Lists the objects for the rays through image points (px, py), x0 ≤ px ≤ x1 and y0 ≤ py
   * ≤ y1, of a width × height image; none for a camera with a lens (its rays start all over
   * the lens) or when the rays' signs differ or the list would be long.
   */
  set(scene: TracerScene, x0: number, y0: number, x1: number, y1: number, width: number, height: number): this {
    this.count = -1;
    const { camera } = scene;
    if (camera.aperture > 0) return this;
    const corners = this.corners;
    // Around the rectangle, each corner a pixel further out (a preview's rays start up to a pixel past its tile).
    for (let i = 0; i < 4; i++) {
      camera.direction(i === 1 || i === 2 ? x1 + 1 : x0 - 1, i < 2 ? y0 - 1 : y1 + 1, width, height, corner).add(camera.eye);
      corners[i * 3] = corner.x;
      corners[i * 3 + 1] = corner.y;
      corners[i * 3 + 2] = corner.z;
    }
    // The walk's order for the direction through the rectangle's centre; a ray whose signs
    // differ (the rectangle straddles a sign change) walks the BVH itself.
    this.backwardAxes = backwardAxes(camera.direction((x0 + x1) / 2, (y0 + y1) / 2, width, height, corner));
    this.cone.throughQuad(camera.eye, corners, scene.epsilon);
    this.count = scene.objects.itemsInCone(this.cone, this.backwardAxes, this.list, this.boxes, MAX_LISTED);
    return this;
  }

  /** Whether the list holds the objects for `ray`, one of the rectangle's rays. */
  covers(ray: Ray): boolean {
    return this.count >= 0 && backwardAxes(ray.direction) === this.backwardAxes;
  }
}

/** Bit k set: the direction is negative along axis k (the walk visits the upper child first there). */
export function backwardAxes(direction: Vector3): number {
  return (direction.x < 0 ? 1 : 0) | (direction.y < 0 ? 2 : 0) | (direction.z < 0 ? 4 : 0);
}
