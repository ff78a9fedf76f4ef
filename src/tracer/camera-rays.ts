import { Vector3 } from 'three';
import type { Camera } from '../scene/scene.ts';

const DEG = Math.PI / 180;

/**
 * The pinhole camera: turns a point on the image (in pixels, y down) into a primary ray.
 * The vertical field of view is `camera.fov`; the horizontal one follows the image's
 * aspect ratio, so a 512×384 render frames the same view as an 8×6 screen.
 */
export class CameraRays {
  readonly eye: Vector3;
  readonly forward = new Vector3();
  readonly right = new Vector3();
  readonly up = new Vector3();
  private readonly tanHalfFov: number;

  constructor(camera: Camera) {
    this.eye = new Vector3(...camera.position);
    this.forward.set(...camera.target).sub(this.eye);
    if (this.forward.lengthSq() === 0) this.forward.set(0, 0, -1);
    this.forward.normalize();
    // up is +Y; a camera looking straight up or down uses +Z/−Z as its "up" hint instead.
    const upHint = Math.abs(this.forward.y) > 0.999 ? new Vector3(0, 0, -Math.sign(this.forward.y)) : new Vector3(0, 1, 0);
    this.right.crossVectors(this.forward, upHint).normalize();
    this.up.crossVectors(this.right, this.forward);
    this.tanHalfFov = Math.tan((camera.fov * DEG) / 2);
  }

  /**
   * The unit direction through image point (px, py) of a width×height image;
   * (0, 0) is the top-left corner of the top-left pixel.
   */
  direction(px: number, py: number, width: number, height: number, out: Vector3): Vector3 {
    const aspect = width / height;
    const sx = ((px / width) * 2 - 1) * this.tanHalfFov * aspect;
    const sy = (1 - (py / height) * 2) * this.tanHalfFov;
    return out
      .copy(this.forward)
      .addScaledVector(this.right, sx)
      .addScaledVector(this.up, sy)
      .normalize();
  }
}
