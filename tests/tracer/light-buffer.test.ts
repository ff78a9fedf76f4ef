import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { LightBuffer } from '../../src/tracer/light-buffer.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { randomPoint, randomShapes as randomShapesOf } from '../support/random-shapes.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

const random = new RandomStream().reset(hashKey(21));
const point = (spread: number) => randomPoint(random, spread);
const randomShapes = (count: number) => randomShapesOf(random, count);

const EPSILON = 1e-4;

/**
 * A shadow ray as the integrator casts it: from ε off a surface point (along a random unit
 * normal, toward the light's side) toward the light, ending ε short of it.
 */
function shadowRay(from: Vector3, light: Vector3, ray: Ray): Ray {
  const toLight = light.clone().sub(from);
  const distance = toLight.length();
  toLight.divideScalar(distance);
  const normal = point(1).normalize();
  const origin = from.clone().addScaledVector(normal, normal.dot(toLight) >= 0 ? EPSILON : -EPSILON);
  ray.set(origin, toLight);
  ray.far = distance - EPSILON;
  return ray;
}

/**
 * The light buffer must answer "is anything between this point and the light" exactly as
 * testing every object does: it may list an object in a cell where it cannot block, never
 * leave one out where it can.
 */
describe('the light buffer of a point light', () => {
  for (const count of [9, 60, 256]) {
    it(`finds a blocker exactly when one of ${count} objects blocks the shadow ray`, () => {
      random.reset(hashKey(21, count));
      const shapes = randomShapes(count);
      const ray = new Ray();
      let blocked = 0;
      let open = 0;
      // Lights among the objects, and some inside an object's box.
      const lights = [point(6), point(3), point(1), shapes[0].worldBounds.getCenter(new Vector3())];
      for (const light of lights) {
        const buffer = new LightBuffer(light, shapes, 4 * EPSILON);
        for (let i = 0; i < 1500; i++) {
          // Surface-like points: on an object's box (near where shadow rays start), or anywhere.
          const from = i % 2 === 0 ? shapes[i % count].worldBounds.clampPoint(point(6), new Vector3()) : point(6);
          shadowRay(from, light, ray);
          const skip = i % 3 === 0 ? shapes[i % count] : null;
          const blocker = buffer.firstBlocker(ray, skip);
          const blockers = shapes.filter((s) => s !== skip && s.occludes(ray));
          expect(blocker === null).toBe(blockers.length === 0);
          if (blocker) {
            expect(blockers).toContain(blocker);
            blocked++;
          } else open++;
        }
      }
      // Both answers, often: the rays must test the buffer, not pass trivially.
      expect(blocked).toBeGreaterThan(300);
      expect(open).toBeGreaterThan(300);
    });
  }

  it('lists an object only in the cells it is seen through', () => {
    // Small balls 5 units along +x and −z: a few cells of the +x and the −z face, none of the others.
    const ball = (position: number[]) => ({ id: `ball${position}`, shape: 'sphere', position, scale: [0.2, 0.2, 0.2], material: matte([1, 1, 1]) });
    const balls = tracerSceneFrom({ objects: [ball([5, 0, 0]), ball([0, 0, -5])] }).shapes;
    const buffer = new LightBuffer(new Vector3(0, 0, 0), balls, 4 * EPSILON);
    const listedIn = (dx: number, dy: number, dz: number) => {
      const cell = buffer.cell(dx, dy, dz);
      return buffer.objects.slice(buffer.starts[cell], buffer.starts[cell + 1]).map((o) => o.id);
    };
    expect(listedIn(1, 0, 0)).toEqual(['ball5,0,0']);
    expect(listedIn(1, 0.01, -0.01)).toEqual(['ball5,0,0']);
    expect(listedIn(0, 0.01, -1)).toEqual(['ball0,0,-5']);
    for (const [dx, dy, dz] of [
      [1, 0.9, 0],
      [-1, 0, 0],
      [0, 1, 0],
      [0, -1, 0],
      [0, 0, 1],
      [0.9, 0, -1],
    ])
      expect(listedIn(dx, dy, dz)).toEqual([]);
    // Each in a handful of cells, not in whole faces.
    expect(buffer.objects.length).toBeLessThan(10);
  });

  it('lists an object around the light in every cell', () => {
    const [box] = tracerSceneFrom({ objects: [{ id: 'shade', shape: 'box', position: [0, 0, 0], scale: [1, 1, 1], material: matte([1, 1, 1]) }] }).shapes;
    const buffer = new LightBuffer(new Vector3(0.1, 0.2, 0), [box], 4 * EPSILON);
    for (let c = 0; c < buffer.starts.length - 1; c++) expect(buffer.starts[c + 1] - buffer.starts[c]).toBe(1);
  });
});
