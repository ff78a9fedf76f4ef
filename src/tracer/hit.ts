import { Vector3 } from 'three';
import type { Intersectable } from './intersectable.ts';

/**
 * The nearest intersection found so far along a ray. Shapes fill `t`, `shape` and the
 * object-space details they need (`local`, `face`); the normals are computed only once,
 * for the final nearest hit (see Shape.surface).
 */
export class Hit {
  t = Infinity;
  shape: Intersectable | null = null;
  /** The hit point in the shape's object space. */
  readonly local = new Vector3();
  /** Triangle index, for meshes. */
  face = -1;
  /** World-space hit point. */
  readonly point = new Vector3();
  /** World-space outward geometric normal (unit): decides inside/outside. */
  readonly geometricNormal = new Vector3();
  /** World-space outward shading normal (unit): interpolated on smooth meshes. */
  readonly normal = new Vector3();

  reset(tMax: number): this {
    this.t = tMax;
    this.shape = null;
    this.face = -1;
    return this;
  }
}
