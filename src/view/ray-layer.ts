import type { Object3D, Raycaster } from 'three';
import type { RayNode, RayType } from '../tracer/ray-tree.ts';
import type { Thinning } from './ray-budget.ts';
import type { RayColorKey } from './ray-palette.ts';

/** What the pointer is over when it hovers a drawn ray (shown in a tooltip). */
export interface RayHover {
  type: RayType;
  /** The legend entry it is drawn as: "normal" for the normal at the hit of `node`. */
  drawnAs: RayColorKey;
  contribution: number;
  color: [number, number, number];
  pixel: [number, number];
  node: RayNode;
  /** Metres from the ray's origin to the point of it nearest the pointer. */
  at: number;
  /** A ray of a pixel's sample paths (path mode): `contribution` is the throughput it carries. */
  path: boolean;
}

/**
 * The drawn rays, as the lab view sees them: a three.js object to add to its scene, a
 * per-frame hook for the growth animation, and picking for hover. Implemented by RayPool
 * (src/view/ray-pool.ts); the view does not know how rays are drawn.
 */
export interface RayLayer {
  readonly object: Object3D;
  /** Advances the animation to `timeMs`; returns true while it needs more frames. */
  tick(timeMs: number): boolean;
  /** The nearest ray under the pointer, or null. */
  pick(raycaster: Raycaster): RayHover | null;
  /** Offers a click on a drawn ray to whoever drew it (RayFocus.chooseRay); true when it was taken. */
  click(hover: RayHover): boolean;
  /** How many rays are drawn of how many while a budget leaves some out (ray-budget.ts); null when all are. */
  readonly thinning: Thinning | null;
  /** The instances `object` draws (rays and cones), counted in the order it draws them, as the pieces below are. */
  readonly instances: number;
  /**
   * From now on `object` draws only its first `count` instances (null: all again): the first
   * piece of a heavy layer drawn over several frames (view/piecewise-rays.ts).
   */
  drawFirst(count: number | null): void;
  /** An object, not in the scene, that draws instances `from` … `from + count − 1` alone, as `object` would. */
  piece(from: number, count: number): Object3D;
}
