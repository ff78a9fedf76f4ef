import { Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Camera, SamplePattern } from '../../src/scene/scene.ts';
import { CameraRays } from '../../src/tracer/camera-rays.ts';
import { samplePosition } from '../../src/tracer/supersampling.ts';
import { cameraRigQuaternion, cellAtUv, cellCenter, samplePoints, screenGrid, screenPoint } from '../../src/view/screen-grid.ts';

const camera: Camera = { position: [1, 2, 6], target: [-0.5, 0.2, -1], fov: 50, pixels: [8, 6], screenDistance: 1.5, aperture: 0, lensSamples: 1 };

/** A local point of the rig, in the world: eye + rotation · point. */
function toWorld(local: Vector3, rays: CameraRays): Vector3 {
  return local.clone().applyQuaternion(cameraRigQuaternion(rays, new Quaternion())).add(rays.eye);
}

describe('the camera screen grid', () => {
  it('is screenDistance in front of the eye, as tall as the vertical fov and as wide as columns/rows (square cells)', () => {
    const grid = screenGrid(camera);
    expect(grid.halfHeight).toBeCloseTo(1.5 * Math.tan((25 * Math.PI) / 180), 12);
    expect(grid.halfWidth / grid.halfHeight).toBeCloseTo(8 / 6, 12);
    expect((2 * grid.halfWidth) / grid.columns).toBeCloseTo((2 * grid.halfHeight) / grid.rows, 12);
  });

  it('puts every cell centre on its pixel-centre primary ray (the ray through it starts at the eye)', () => {
    const rays = new CameraRays(camera);
    const grid = screenGrid(camera);
    const [columns, rows] = camera.pixels;
    for (let y = 0; y < rows; y++) {
      for (let x = 0; x < columns; x++) {
        const world = toWorld(cellCenter(grid, x, y, new Vector3()), rays);
        const fromEye = world.sub(rays.eye);
        const primary = rays.direction(x + 0.5, y + 0.5, columns, rows, new Vector3());
        expect(fromEye.clone().normalize().distanceTo(primary)).toBeLessThan(1e-12);
        // …and at screenDistance along the viewing direction.
        expect(fromEye.dot(rays.forward)).toBeCloseTo(camera.screenDistance, 12);
      }
    }
  });

  it('counts rows from the top, like the tracer: pixel (0, 0) is the top-left cell', () => {
    const grid = screenGrid(camera);
    const topLeft = cellCenter(grid, 0, 0, new Vector3());
    expect(topLeft.x).toBeLessThan(0);
    expect(topLeft.y).toBeGreaterThan(0);
    expect(screenPoint(grid, 8, 6, new Vector3()).toArray()).toEqual([grid.halfWidth, -grid.halfHeight, -1.5]);
  });

  it('maps texture coordinates back to the cell they fall in (v up, rows down), edges included', () => {
    expect(cellAtUv(0, 1, 8, 6)).toEqual([0, 0]);
    expect(cellAtUv(1, 0, 8, 6)).toEqual([7, 5]);
    expect(cellAtUv(2.5 / 8, 1 - 1.5 / 6, 8, 6)).toEqual([2, 1]);
    expect(cellAtUv(0.125, 0.5, 8, 6)).toEqual([1, 3]);
    expect(cellAtUv(-0.01, 0.5, 8, 6)).toBeNull();
    expect(cellAtUv(0.5, 1.01, 8, 6)).toBeNull();
  });

  it.each<SamplePattern>(['grid', 'jittered', 'random'])('places %s sample points exactly where the tracer samples', (pattern) => {
    const small: Camera = { ...camera, pixels: [3, 2] };
    const grid = screenGrid(small);
    const s = 3;
    const points = samplePoints(grid, s, pattern, new Float32Array(3 * 2 * s * s * 3));
    const offset = [0, 0] as [number, number];
    let i = 0;
    for (let y = 0; y < 2; y++) {
      for (let x = 0; x < 3; x++) {
        for (let k = 0; k < s * s; k++, i++) {
          samplePosition(pattern, s, k, x, y, 0, offset);
          const expected = screenPoint(grid, x + offset[0], y + offset[1], new Vector3());
          expect(points[3 * i]).toBeCloseTo(expected.x, 6);
          expect(points[3 * i + 1]).toBeCloseTo(expected.y, 6);
          expect(points[3 * i + 2]).toBeCloseTo(-1.5, 6);
          // Inside its own pixel's cell.
          expect(cellAtUv(points[3 * i] / (2 * grid.halfWidth) + 0.5, points[3 * i + 1] / (2 * grid.halfHeight) + 0.5, 3, 2)).toEqual([x, y]);
        }
      }
    }
  });

  it('keeps jittered points inside their own sub-cell, and grid points at sub-cell centres', () => {
    const one: Camera = { ...camera, pixels: [1, 1] };
    const grid = screenGrid(one);
    const s = 4;
    for (const pattern of ['grid', 'jittered'] as const) {
      const points = samplePoints(grid, s, pattern, new Float32Array(s * s * 3));
      for (let k = 0; k < s * s; k++) {
        const u = points[3 * k] / (2 * grid.halfWidth) + 0.5;
        const down = 0.5 - points[3 * k + 1] / (2 * grid.halfHeight);
        expect(Math.floor(u * s)).toBe(k % s);
        expect(Math.floor(down * s)).toBe(Math.floor(k / s));
        if (pattern === 'grid') expect(u * s - Math.floor(u * s)).toBeCloseTo(0.5, 5);
      }
    }
  });
});
