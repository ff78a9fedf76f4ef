import { readFileSync } from 'node:fs';
import { DoubleSide, Ray as ThreeRay, Vector3 } from 'three';
import { beforeAll, describe, expect, it } from 'vitest';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import type { MeshData } from '../../src/scene/mesh-data.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { meshAccel } from '../../src/tracer/shapes/mesh-accel.ts';
import { meshNearest, nearest } from '../../src/tracer/shapes/mesh-nearest.ts';

/**
 * The tracer's own nearest-hit walk of a model's BVH must find exactly what three-mesh-bvh's
 * raycastFirst finds, to the bit and to the triangle, ties included: the image depends on
 * the triangle (its normal) as well as on the distance.
 *
 * This file is the guard of three-mesh-bvh's internal node layout, which mesh-walk.ts reads
 * directly: package.json pins three-mesh-bvh to one exact version (no `^`), so a new
 * version arrives only by editing that pin, and then these tests say whether the layout
 * still holds.
 */
let character: MeshData;

beforeAll(async () => {
  character = (await loadMeshesFromDisk(['character'])).get('character')!;
});

/** raycastFirst's distance and triangle for o + t·d, t < tMax (d of any length, as the tracer passes it). */
function threeMeshBvhNearest(o: Vector3, d: Vector3, tMax: number): { distance: number; face: number } {
  const accel = meshAccel(character);
  const unit = new ThreeRay(o.clone(), d.clone().divideScalar(d.length()));
  const result = accel.bvh.raycastFirst(unit, DoubleSide, 0, tMax * d.length());
  return result ? { distance: result.distance, face: result.faceIndex! } : { distance: Infinity, face: -1 };
}

function ours(o: Vector3, d: Vector3, tMax: number): { distance: number; face: number } {
  const found = meshNearest(meshAccel(character), o, d, tMax);
  expect(found).toBe(nearest.distance !== Infinity);
  return { distance: nearest.distance, face: found ? nearest.face : -1 };
}

describe('three-mesh-bvh, whose node layout the tracer reads', () => {
  it('is pinned to one exact version in package.json, and that version is installed', () => {
    const read = (path: string) => JSON.parse(readFileSync(new URL(path, import.meta.url), 'utf8'));
    const pinned: string = read('../../package.json').dependencies['three-mesh-bvh'];
    expect(pinned).toMatch(/^\d+\.\d+\.\d+$/);
    expect(read('../../node_modules/three-mesh-bvh/package.json').version).toBe(pinned);
  });
});

describe('the nearest hit on a model', () => {
  it('is raycastFirst’s, to the bit, on rays at random points and at the model’s vertices', () => {
    const { positions } = character;
    const random = new RandomStream().reset(hashKey(31, 7));
    const along = () => random.next() * 2 - 1;
    let hits = 0;
    for (let i = 0; i < 1500; i++) {
      const o = new Vector3(along(), along(), along()).normalize().multiplyScalar(3);
      // Every other ray aims exactly at a vertex, where several triangles meet at one distance.
      const vertex = Math.floor(random.next() * (positions.length / 3));
      const target = i % 2 ? new Vector3().fromArray(positions, vertex * 3) : new Vector3(along() * 0.3, along() * 0.5, along() * 0.2);
      // Unnormalized, as a shape passes its object-space direction; a far limit on some rays.
      const d = target.sub(o).multiplyScalar(0.5 + random.next());
      const tMax = i % 3 === 0 ? 2.5 : Infinity;
      const expected = threeMeshBvhNearest(o, d, tMax);
      expect(ours(o, d, tMax)).toEqual(expected);
      if (expected.distance !== Infinity) hits++;
    }
    expect(hits).toBeGreaterThan(600);
  });

  it('misses a ray that passes the model by', () => {
    expect(ours(new Vector3(0, 5, 5), new Vector3(0, 0, -1), Infinity)).toEqual({ distance: Infinity, face: -1 });
  });
});
