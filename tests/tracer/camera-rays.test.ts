import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { tracerSceneFrom } from '../support/test-scene.ts';

describe('CameraRays.pixelSpread', () => {
  // A shadow patch is sized by it (whitted-integrator.ts): it must be the real distance
  // between neighbouring pixels' rays where they cross the plane 1 m in front of the eye.
  it.each([
    [50, 256],
    [30, 120],
    [80, 17],
  ])('is the side of a central pixel at distance 1 (fov %i°, %i pixels high)', (fov, height) => {
    const { camera } = tracerSceneFrom({ camera: { position: [0, 1, 4], target: [0, 0, 0], fov } });
    const atDistanceOne = (px: number, py: number) => {
      const direction = camera.direction(px, py, height, height, new Vector3());
      return direction.divideScalar(direction.dot(camera.forward));
    };
    const centre = height / 2;
    const across = atDistanceOne(centre + 0.5, centre).distanceTo(atDistanceOne(centre - 0.5, centre));
    const down = atDistanceOne(centre, centre + 0.5).distanceTo(atDistanceOne(centre, centre - 0.5));
    expect(camera.pixelSpread(height)).toBeCloseTo(across, 12);
    expect(camera.pixelSpread(height)).toBeCloseTo(down, 12);
  });
});
