import { Vector3 } from 'three';
import { effectiveFocusDistance } from '../scene/camera-focus.ts';
import type { Camera } from '../scene/scene.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';

/**
 * The camera: turns a point on the image (in pixels, y down) into a primary ray.
 * The vertical field of view is `camera.fov`; the horizontal one follows the image's
 * aspect ratio, so a 512×384 render frames the same view as an 8×6 screen.
 *
 * With an aperture it is a thin lens (Cook, Porter & Carpenter 1984; Potmesil & Chakravarty
 * 1981): the pinhole ray through an image point meets the plane in focus at F, and the lens
 * rays go from points on a disc of radius `aperture` around the eye, in the camera's
 * right/up plane, toward F (distribution-effects §2). Points on that plane are sharp whatever
 * the aperture; a point at distance z is spread over a circle of confusion of diameter
 * 2a·|z − z_f|/z on the plane in focus (z_f the focus distance, a the lens radius).
 */
export class CameraRays {
  readonly eye: Vector3;
  readonly forward = new Vector3();
  readonly right = new Vector3();
  readonly up = new Vector3();
  private readonly tanHalfFov: number;
  /** Lens radius a in metres; 0 is the pinhole. */
  readonly aperture: number;
  /** f: distance of the plane in focus along `forward`. */
  readonly focusDistance: number;
  /** n: n×n lens points per pixel sample, 1 for a pinhole (where n is ignored). */
  readonly lensSamplesPerSide: number;

  constructor(camera: Camera) {
    this.eye = new Vector3(...camera.position);
    this.forward.set(...camera.target).sub(this.eye);
    if (this.forward.lengthSq() === 0) this.forward.set(0, 0, -1);
    this.forward.normalize();
    // up is +Y; a camera looking straight up or down uses +Z/−Z as its "up" hint instead.
    const upHint = Math.abs(this.forward.y) > 0.999 ? new Vector3(0, 0, -Math.sign(this.forward.y)) : new Vector3(0, 1, 0);
    this.right.crossVectors(this.forward, upHint).normalize();
    this.up.crossVectors(this.right, this.forward);
    this.tanHalfFov = Math.tan((camera.fov * RADIANS_PER_DEGREE) / 2);
    this.aperture = camera.aperture;
    this.focusDistance = effectiveFocusDistance(camera);
    this.lensSamplesPerSide = camera.aperture > 0 ? camera.lensSamples : 1;
  }

  /** F: where the pinhole ray along unit `direction` meets the plane in focus. */
  focalPoint(direction: Vector3, out: Vector3): Vector3 {
    return out.copy(this.eye).addScaledVector(direction, this.focusDistance / direction.dot(this.forward));
  }

  /** The lens point of unit-disc point (u, v): eye + aperture·(u·right + v·up). */
  lensPoint(u: number, v: number, out: Vector3): Vector3 {
    return out
      .copy(this.eye)
      .addScaledVector(this.right, this.aperture * u)
      .addScaledVector(this.up, this.aperture * v);
  }

  /** The side of one pixel of an image `height` pixels high, at distance 1 in front of the eye. */
  pixelSpread(height: number): number {
    return (2 * this.tanHalfFov) / height;
  }

  /**
   * The unit direction through image point (px, py) of a width×height image;
   * (0, 0) is the top-left corner of the top-left pixel.
   */
  direction(px: number, py: number, width: number, height: number, out: Vector3): Vector3 {
    const aspect = width / height;
    const sx = ((px / width) * 2 - 1) * this.tanHalfFov * aspect;
    const sy = (1 - (py / height) * 2) * this.tanHalfFov;
    return out.copy(this.forward).addScaledVector(this.right, sx).addScaledVector(this.up, sy).normalize();
  }
}
