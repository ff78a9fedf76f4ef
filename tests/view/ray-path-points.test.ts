import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/scene/scene.ts';
import type { PixelTrace, RayNode } from '../../src/tracer/ray-tree.ts';
import { MISS_REACH, rayPathPoints, rayPathPointsFromHit } from '../../src/view/ray-path-points.ts';
import { framingPose } from '../../src/view/view-pose.ts';

function node(type: RayNode['type'], origin: Vec3, direction: Vec3, length: number, hit: boolean, children: RayNode[] = []): RayNode {
  return { type, origin, direction, length, hit, objectId: null, lightId: null, color: [0, 0, 0], contribution: 1, children };
}

// A primary ray 4 m down −z to a mirror, a reflection 2 m up that hits nothing, a light ray 3 m along +x.
const trace: PixelTrace = {
  pixel: [2, 1],
  color: [0, 0, 0],
  rays: [node('primary', [0, 1, 4], [0, 0, -1], 4, true, [node('reflect', [0, 1, 0], [0, 1, 0], 10, false), node('light', [0, 1, 0], [1, 0, 0], 3, true)])],
};

describe("framing a pixel's rays", () => {
  it('takes every start and end, and only the first metre of a ray that hit nothing', () => {
    expect(rayPathPoints(trace)).toEqual([
      [0, 1, 4],
      [0, 1, 0],
      [0, 1, 0],
      [0, 1 + MISS_REACH, 0],
      [0, 1, 0],
      [3, 1, 0],
    ]);
  });

  it('frames what the rays do after their first hit: not the camera, and only the first metre toward a lamp', () => {
    expect(rayPathPointsFromHit(trace)).toEqual([
      [0, 1, 0],
      [0, 1, 0],
      [0, 1 + MISS_REACH, 0],
      [0, 1, 0],
      [MISS_REACH, 1, 0],
    ]);
  });

  it('frames them from the side the view looks from now, every point in view', () => {
    const points = rayPathPoints(trace);
    const from = new Vector3(1, 0, 0);
    const pose = framingPose(points, points, 50, 1.5, from);
    const toEye = pose.position.clone().sub(pose.target).normalize();
    expect(toEye.distanceTo(from)).toBeLessThan(1e-9);
    // Far enough back: every point within the vertical half-angle seen from the eye.
    const half = (50 * Math.PI) / 360;
    for (const point of points) {
      const toPoint = new Vector3(...point).sub(pose.position);
      const forward = pose.target.clone().sub(pose.position).normalize();
      expect(toPoint.angleTo(forward)).toBeLessThanOrEqual(half + 1e-9);
    }
  });
});
