import type { Box3 } from 'three';
import type { Material } from '../scene/scene.ts';
import type { Hit } from './hit.ts';
import type { Ray } from './ray.ts';

/**
 * What the integrator needs of a scene object. The tracer's own implementation is Shape;
 * the benchmark plugs in a three.js Raycaster version to compare against the same shading.
 */
export interface Intersectable {
  readonly id: string;
  readonly material: Material;
  /** A ray leaving a convex object's outer surface cannot hit it again. */
  readonly convex: boolean;
  /** It encloses a volume (not a flat plane): when convex too, a ray from inside it meets its surface whichever way it goes. */
  readonly solid: boolean;
  /** World-space bounding box: rays that miss it cannot hit the object. */
  readonly worldBounds: Box3;
  /** If hit nearer than `hit.t` (and farther than 0): records the hit and returns true. */
  intersect(ray: Ray, hit: Hit): boolean;
  /** Any-hit: whether it is hit nearer than `ray.far` (and farther than 0), exactly when `intersect` would hit. */
  occludes(ray: Ray): boolean;
  /** Fills hit.point and the outward unit normals, for the nearest hit only. */
  surface(ray: Ray, hit: Hit): void;
}
