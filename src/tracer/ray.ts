import { Vector3 } from 'three';

/** A ray with a unit direction; `t` along it is a distance in metres. */
export class Ray {
  readonly origin = new Vector3();
  readonly direction = new Vector3();
  /** 1/direction per axis, for the slab test against bounding boxes. */
  readonly inverseDirection = new Vector3();
  /** τ in [0, 1): when in the open shutter the ray is cast; moving objects are at position + τ·velocity. */
  time = 0;
  /**
   * How far an any-hit test looks (Intersectable.occludes): only hits at t < far count. A
   * field, not an argument: docs/performance.md, "Numbers passed to calls".
   */
  far = Infinity;
  /**
   * Per axis, where the side of a box the ray enters through lies in the box's six numbers
   * (min x, y, z, max x, y, z): the max when the ray goes toward −axis, else the min. For
   * the slab test (ray-box.ts).
   */
  nearX = 0;
  nearY = 1;
  nearZ = 2;

  /** Sets origin and direction; the time is kept (a ray's children share it). */
  set(origin: Vector3, direction: Vector3): this {
    this.origin.copy(origin);
    this.direction.copy(direction);
    const inverse = this.inverseDirection.set(1 / direction.x, 1 / direction.y, 1 / direction.z);
    this.nearX = inverse.x < 0 ? 3 : 0;
    this.nearY = inverse.y < 0 ? 4 : 1;
    this.nearZ = inverse.z < 0 ? 5 : 2;
    return this;
  }
}
