import { Box3, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { Hit } from '../../src/tracer/hit.ts';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import { ObjectBvh } from '../../src/tracer/object-bvh.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { between as betweenOf, randomPoint, randomShapes as randomShapesOf } from '../support/random-shapes.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

const random = new RandomStream().reset(hashKey(12));
const between = (low: number, high: number) => betweenOf(random, low, high);
const point = (spread: number) => randomPoint(random, spread);
const randomShapes = (count: number) => randomShapesOf(random, count);

/**
 * The object BVH must give exactly what testing every object in the scene's order gives:
 * the same nearest object at the same distance, the same answer to "is anything in the way",
 * and the same objects overlapping a box, with objects skipped and boxes limiting the search.
 */
describe('the BVH over objects', () => {
  for (const count of [5, 40, 256]) {
    it(`answers as a linear search does, over ${count} objects`, () => {
      random.reset(hashKey(12, count));
      const shapes = randomShapes(count);
      const bvh = new ObjectBvh(shapes);
      const ray = new Ray();
      const [fromBvh, fromAll] = [new Hit(), new Hit()];
      let hits = 0;
      let blocked = 0;
      for (let i = 0; i < 3000; i++) {
        // Aimed near one of the objects, so that many rays hit.
        const origin = point(6);
        const target = shapes[i % count].worldBounds.getCenter(new Vector3()).add(point(0.5));
        ray.set(origin, target.sub(origin).normalize());
        const skip = i % 3 === 0 ? shapes[i % count] : null;
        const within = i % 2 === 0 ? new Box3().setFromPoints([point(5), point(5)]) : null;
        const tested = shapes.filter((s) => s !== skip && (!within || s.worldBounds.intersectsBox(within)));
        // Walks from the root, and from an object's leaf (any object: correctness cannot
        // depend on where the ray really starts).
        const from = i % 4 < 2 ? null : shapes[(i * 7) % count];

        fromBvh.reset(Infinity);
        bvh.nearest(ray, fromBvh, skip, within, from);
        fromAll.reset(Infinity);
        for (const shape of tested) shape.intersect(ray, fromAll);
        expect([fromBvh.shape?.id, fromBvh.t]).toEqual([fromAll.shape?.id, fromAll.t]);
        if (fromAll.shape) hits++;

        ray.far = between(0, 12);
        const reach = within ?? new Box3(new Vector3(-9, -9, -9), new Vector3(9, 9, 9));
        const blocker = bvh.firstBlocker(ray, skip, reach, from);
        const blocks = tested.filter((s) => s.worldBounds.intersectsBox(reach) && s.occludes(ray));
        expect(blocker === null).toBe(blocks.length === 0);
        if (blocker) {
          expect(blocks).toContain(blocker);
          blocked++;
        }
      }
      expect(hits).toBeGreaterThan(200);
      expect(blocked).toBeGreaterThan(200);
    });

    it(`lists the objects overlapping a box, stopping past a limit, over ${count} objects`, () => {
      random.reset(hashKey(13, count));
      const shapes = randomShapes(count);
      const bvh = new ObjectBvh(shapes);
      const found: Intersectable[] = [];
      for (let i = 0; i < 500; i++) {
        const box = new Box3().setFromPoints([point(5), point(5)]);
        const expected = shapes.filter((s) => s.worldBounds.intersectsBox(box));
        const from = i % 2 === 0 ? null : shapes[i % count];
        const end = bvh.overlapping(box, found, 1, Infinity, null, from);
        expect(new Set(found.slice(1, end))).toEqual(new Set(expected));
        expect(end - 1).toBe(expected.length);
        const limited = bvh.overlapping(box, found, 0, 2, null, from);
        expect(limited).toBe(Math.min(expected.length, limited));
        if (expected.length > 2) expect(limited).toBeGreaterThan(2);
        else expect(limited).toBe(expected.length);
      }
    });
  }

  it('starts a ray leaving an object at that object, skipping the boxes around it', () => {
    // 64 spheres in a row along x; a ray leaving s20 upward meets nothing.
    const objects = Array.from({ length: 64 }, (_, i) => ({ id: `s${i}`, shape: 'sphere', position: [i * 2, 0, 0], material: matte([1, 1, 1]) }));
    const shapes = tracerSceneFrom({ objects }).shapes;
    const bvh = new ObjectBvh(shapes);
    const ray = new Ray().set(new Vector3(40, 0.5, 0), new Vector3(0.1, 1, 0).normalize());
    // Each box test and object test reads the ray's origin once.
    const boxTests = (from: Intersectable | null) => {
      const tests = { count: 0 };
      const counted = new Proxy(ray, { get: (target, key) => (key === 'origin' && tests.count++, Reflect.get(target, key)) });
      bvh.nearest(counted, new Hit().reset(Infinity), shapes[20], null, from);
      return tests.count;
    };
    // 64 objects two to a leaf: five boxes above s20's leaf, each holding the ray's start.
    // Started at the leaf, the walk tests none of them, and the same boxes and objects besides.
    expect(boxTests(shapes[20])).toBe(boxTests(null) - 5);
  });

  it('tests the objects front to back, so that a near hit skips the far ones', () => {
    // 64 spheres in a row along x; a ray along the row from either end hits the first one.
    const objects = Array.from({ length: 64 }, (_, i) => ({ id: `s${i}`, shape: 'sphere', position: [i * 2, 0, 0], material: matte([1, 1, 1]) }));
    const shapes = tracerSceneFrom({ objects }).shapes;
    let tested = 0;
    for (const shape of shapes) {
      const intersect = shape.intersect.bind(shape);
      shape.intersect = (ray, hit) => {
        tested++;
        return intersect(ray, hit);
      };
    }
    const bvh = new ObjectBvh(shapes);
    for (const [from, direction, first] of [
      [-10, 1, 's0'],
      [140, -1, 's63'],
    ] as const) {
      tested = 0;
      const hit = new Hit().reset(Infinity);
      bvh.nearest(new Ray().set(new Vector3(from, 0.01, 0.02), new Vector3(direction, 0, 0)), hit, null);
      expect(hit.shape?.id).toBe(first);
      // Back to front it would test every sphere (each is nearer than the last).
      expect(tested).toBeLessThanOrEqual(4);
    }
  });
});
