import { Vector3 } from 'three';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import type { RandomStream } from '../../src/tracer/sampler.ts';
import { matte, tracerSceneFrom } from './test-scene.ts';

/** A number drawn evenly from low … high. */
export const between = (random: RandomStream, low: number, high: number) => low + (high - low) * random.next();

/** A point in the cube of half-side `spread` around the origin. */
export const randomPoint = (random: RandomStream, spread: number) =>
  new Vector3(between(random, -spread, spread), between(random, -spread, spread), between(random, -spread, spread));

/** `count` shapes of every kind at random places and sizes around the origin, overlapping one another. */
export function randomShapes(random: RandomStream, count: number): readonly Intersectable[] {
  const kinds = ['sphere', 'box', 'cylinder', 'plane'];
  const objects = Array.from({ length: count }, (_, i) => ({
    id: `o${i}`,
    shape: kinds[i % kinds.length],
    position: randomPoint(random, 4).toArray(),
    rotation: [between(random, 0, 90), between(random, 0, 90), between(random, 0, 90)],
    scale: [between(random, 0.2, 1.5), between(random, 0.2, 1.5), between(random, 0.2, 1.5)],
    material: matte([1, 1, 1]),
  }));
  return tracerSceneFrom({ objects }).shapes;
}
