import { Vector3 } from 'three';
import type { Vec3 } from '../code-lab-grading.ts';
import { v } from '../lab-vectors.ts';
import type { LabRenderScene } from './lab-render-scene.ts';

/** The ray a lab render sends through one point of the picture: where it starts and its unit direction. */
export interface PixelRay {
  origin: Vec3;
  direction: Vec3;
}

/** Where a lab render looks from: the ray through the point (x, y) of a width × height picture, y down from the top. */
export type LabCamera = (x: number, y: number, width: number, height: number) => PixelRay;

/** The level's own camera: every ray from its eye, through the pixel (the tracer's pinhole camera). */
export function levelCamera(scene: LabRenderScene): LabCamera {
  const { camera } = scene.others;
  const origin = v(camera.eye.x, camera.eye.y, camera.eye.z);
  const direction = new Vector3();
  return (x, y, width, height) => {
    camera.direction(x, y, width, height, direction);
    return { origin, direction: v(direction.x, direction.y, direction.z) };
  };
}
