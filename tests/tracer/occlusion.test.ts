import { TorusKnotGeometry, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { ShapeKind } from '../../src/scene/scene.ts';
import { Hit } from '../../src/tracer/hit.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

function torusKnot() {
  const geometry = new TorusKnotGeometry(0.3, 0.1, 96, 12);
  return {
    positions: geometry.getAttribute('position').array as Float32Array,
    normals: null,
    indices: new Uint32Array(geometry.getIndex()!.array),
  };
}

/**
 * Shadow rays ask only "is anything in the way?" (Shape.occludes, the mesh's own any-hit
 * walk over the BVH buffers). The answer must be exactly the nearest-hit test's, for every
 * ray and every distance, or the shadows in the image would change.
 */
describe('any-hit occlusion', () => {
  const kinds: ShapeKind[] = ['sphere', 'box', 'cylinder', 'plane', 'mesh'];
  for (const kind of kinds) {
    it(`a ${kind} occludes exactly when the nearest-hit test finds it before the distance`, () => {
      const scene = tracerSceneFrom(
        {
          objects: [
            {
              id: 'it',
              shape: kind,
              ...(kind === 'mesh' ? { mesh: 'character' } : {}),
              position: [0.2, -0.1, 0.1],
              rotation: [20, 40, -10],
              scale: [1.5, 0.8, 1.2],
              material: matte([1, 1, 1]),
            },
          ],
        },
        new Map([['character', torusKnot()]]),
      );
      const shape = scene.shapes[0];
      const random = new RandomStream().reset(hashKey(7, kinds.indexOf(kind)));
      const ray = new Ray();
      const hit = new Hit();
      let blocked = 0;
      let open = 0;
      for (let i = 0; i < 4000; i++) {
        const origin = new Vector3(random.next() - 0.5, random.next() - 0.5, random.next() - 0.5).multiplyScalar(4);
        const target = new Vector3(random.next() - 0.5, random.next() - 0.5, random.next() - 0.5).multiplyScalar(1.2);
        ray.set(origin, target.sub(origin).normalize());
        // Distances from short of the object to past it: blocked and unblocked rays both.
        ray.far = random.next() * 4;
        const nearest = shape.intersect(ray, hit.reset(ray.far));
        expect(shape.occludes(ray)).toBe(nearest);
        if (nearest) blocked++;
        else open++;
      }
      expect(blocked).toBeGreaterThan(400);
      expect(open).toBeGreaterThan(400);
    });
  }
});
