import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/scene/scene.ts';
import { cameraViewFov, easeInOutCubic, framingPose, framingPoseAbove, gestureActions, interpolatePose, type ViewPose } from '../../src/view/view-pose.ts';

function pose(position: Vec3, target: Vec3, fov = 45): ViewPose {
  return { position: new Vector3(...position), target: new Vector3(...target), fov };
}

const start = pose([0, 2, 8], [0, 0.5, 0]);

describe('what a gesture did to the view', () => {
  it('is an orbit when the eye turned around an unmoved target at the same distance', () => {
    const turned = start.position.clone().applyAxisAngle(new Vector3(0, 1, 0), 0.3);
    expect(gestureActions(start, pose(turned.toArray(), [0, 0.5, 0]))).toEqual([{ type: 'view.orbited' }]);
  });

  it('is a pan when eye and target slid together', () => {
    expect(gestureActions(start, pose([1, 2.5, 8], [1, 1, 0]))).toEqual([{ type: 'view.panned' }]);
  });

  it('is a zoom when only the distance to the target changed', () => {
    expect(gestureActions(start, pose([0, 1.25, 4], [0, 0.5, 0]))).toEqual([{ type: 'view.zoomed' }]);
  });

  it('can be a pan and a zoom at once (two fingers)', () => {
    expect(gestureActions(start, pose([1, 1.25, 4], [1, 0.5, 0]))).toEqual([{ type: 'view.panned' }, { type: 'view.zoomed' }]);
  });

  it('is nothing for a click that wobbled by float noise', () => {
    expect(gestureActions(start, pose([1e-7, 2, 8 + 1e-7], [0, 0.5, 0]))).toEqual([]);
  });

  it('counts an orbit across the ±180° seam as small, not as a whole turn', () => {
    const a = pose([-0.01, 0, -5], [0, 0, 0]);
    const b = pose([0.01, 0, -5], [0, 0, 0]);
    expect(gestureActions(a, b)).toEqual([{ type: 'view.orbited' }]);
    expect(gestureActions(a, a)).toEqual([]);
  });
});

describe('the camera flight', () => {
  it('eases in and out: starts and ends still, halfway at half time, never overshoots', () => {
    expect(easeInOutCubic(0)).toBe(0);
    expect(easeInOutCubic(1)).toBe(1);
    expect(easeInOutCubic(0.5)).toBeCloseTo(0.5, 12);
    expect(easeInOutCubic(0.05)).toBeLessThan(0.05);
    expect(easeInOutCubic(0.95)).toBeGreaterThan(0.95);
    expect(easeInOutCubic(1.7)).toBe(1);
    expect(easeInOutCubic(-1)).toBe(0);
  });

  it('moves eye, target and field of view together', () => {
    const to = pose([4, 4, 4], [1, 1, 1], 65);
    const mid = interpolatePose(start, to, 0.5, pose([0, 0, 0], [0, 0, 0]));
    expect(mid.position.toArray()).toEqual([2, 3, 6]);
    expect(mid.target.toArray()).toEqual([0.5, 0.75, 0.5]);
    expect(mid.fov).toBe(55);
  });
});

describe('the first view of a scene', () => {
  it('looks at the middle of the objects and camera, from the front left and above, with every point in view', () => {
    const objects: Vec3[] = [
      [-1.5, 0.5, 0.3],
      [1, 0.5, 1.2],
      [-0.8, 0.35, -2.4],
      [0, 1, 5],
    ];
    const lights: Vec3[] = [
      [2, 4, 3],
      [-1.5, 3, 0.3],
    ];
    for (const aspect of [16 / 9, 1, 0.6]) {
      const framed = framingPose(objects, [...objects, ...lights], 45, aspect);
      expect(framed.target.toArray().map((v) => Number(v.toFixed(3)))).toEqual([-0.25, 0.675, 1.3]);
      expect(framed.position.x).toBeLessThan(framed.target.x);
      expect(framed.position.y).toBeGreaterThan(framed.target.y);
      expect(framed.position.z).toBeGreaterThan(framed.target.z);
      const camera = new PerspectiveCamera(45, aspect, 0.05, 500);
      camera.position.copy(framed.position);
      camera.lookAt(framed.target);
      camera.updateMatrixWorld();
      for (const point of [...objects, ...lights]) {
        const ndc = new Vector3(...point).project(camera);
        expect(Math.abs(ndc.x)).toBeLessThan(1);
        expect(Math.abs(ndc.y)).toBeLessThan(1);
      }
    }
  });
});

describe("the view at the tracer's camera", () => {
  /** Where the tracer screen's corners land in a view of `viewAspect` (normalised device coordinates). */
  function corners(fovDeg: number, columns: number, rows: number, viewAspect: number) {
    const camera = new PerspectiveCamera(cameraViewFov(fovDeg, columns / rows, viewAspect), viewAspect, 0.1, 100);
    camera.updateMatrixWorld();
    const tan = Math.tan((fovDeg * Math.PI) / 360);
    const x = tan * (columns / rows);
    return [
      [-x, tan],
      [x, -tan],
    ].map(([cx, cy]) => new Vector3(cx, cy, -1).project(camera));
  }

  it('shows every column of a screen wider than the view, with a margin', () => {
    // Level 7's 10×6 screen in a 1.2:1 view: by height alone only ~72 % of its width would show.
    for (const corner of corners(50, 10, 6, 1.2)) {
      expect(Math.abs(corner.x)).toBeCloseTo(1 / 1.1, 6);
      expect(Math.abs(corner.y)).toBeLessThan(1 / 1.1);
    }
  });

  it('shows every row of a screen narrower than the view, with a margin', () => {
    for (const corner of corners(40, 6, 4, 2)) {
      expect(Math.abs(corner.y)).toBeCloseTo(1 / 1.1, 6);
      expect(Math.abs(corner.x)).toBeLessThan(1);
    }
  });
});

describe('framing above panels that cover the bottom of the view', () => {
  it('centres what it frames in the free band at the top, and keeps every point inside it', () => {
    const points: Vec3[] = [
      [-1, 0, 0],
      [1, 0, 0],
      [0, 1, 0],
      [0, -1, 0],
    ];
    const direction = new Vector3(0, 0, 1);
    const share = 0.6;
    const pose = framingPoseAbove(points, 45, 1.5, direction, share);
    const camera = new PerspectiveCamera(45, 1.5, 0.01, 100);
    camera.position.copy(pose.position);
    camera.lookAt(pose.target);
    camera.updateMatrixWorld();
    // Screen y from −1 (bottom) to 1 (top): the free band is y > 1 − 2·share.
    const bandBottom = 1 - 2 * share;
    const centre = new Vector3(0, 0, 0).project(camera);
    expect(centre.x).toBeCloseTo(0);
    expect(centre.y).toBeCloseTo((1 + bandBottom) / 2);
    for (const point of points) {
      const seen = new Vector3(...point).project(camera);
      expect(seen.y).toBeGreaterThanOrEqual(bandBottom - 1e-9);
      expect(seen.y).toBeLessThanOrEqual(1 + 1e-9);
      expect(Math.abs(seen.x)).toBeLessThanOrEqual(1 + 1e-9);
    }
  });

  it('is the plain framing when nothing is covered', () => {
    const points: Vec3[] = [
      [0, 0, 0],
      [2, 1, 0],
    ];
    const direction = new Vector3(-0.5, 0.45, 0.74).normalize();
    const above = framingPoseAbove(points, 45, 1.5, direction, 1);
    const plain = framingPose(points, points, 45, 1.5, direction);
    expect(above.position.distanceTo(plain.position)).toBeCloseTo(0);
    expect(above.target.distanceTo(plain.target)).toBeCloseTo(0);
  });
});
