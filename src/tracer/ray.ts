import { Vector3 } from 'three';

/** A ray with a unit direction; `t` along it is a distance in metres. */
export class Ray {
  readonly origin = new Vector3();
  readonly direction = new Vector3();
  /** 1/direction per axis, for the slab test against bounding boxes. */
  readonly inverseDirection = new Vector3();

  set(origin: Vector3, direction: Vector3): this {
    this.origin.copy(origin);
    this.direction.copy(direction);
    this.inverseDirection.set(1 / direction.x, 1 / direction.y, 1 / direction.z);
    return this;
  }
}
