import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { Ray } from '../../src/tracer/ray.ts';
import { rayMeetsBox } from '../../src/tracer/ray-box.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';

/** The textbook slab test (Kay & Kajiya 1986): per axis the min and max of both sides' distances. */
function textbookMeets(ray: Ray, box: Float64Array, tMax: number): boolean {
  let near = -Infinity;
  let far = Infinity;
  for (let k = 0; k < 3; k++) {
    const o = ray.origin.getComponent(k);
    const inverse = ray.inverseDirection.getComponent(k);
    const t0 = (box[k] - o) * inverse;
    const t1 = (box[k + 3] - o) * inverse;
    near = Math.max(near, Math.min(t0, t1));
    far = Math.min(far, Math.max(t0, t1));
  }
  return !(near > far || far < 0 || near > tMax);
}

const random = new RandomStream().reset(hashKey(7));
const between = (low: number, high: number) => low + (high - low) * random.next();

describe('the ray–box slab test', () => {
  it('answers as the textbook test does, in every direction, axis-parallel ones and −0 included', () => {
    const ray = new Ray();
    const box = new Float64Array(6);
    let met = 0;
    for (let i = 0; i < 20000; i++) {
      for (let k = 0; k < 3; k++) {
        const [a, b] = [between(-2, 2), between(-2, 2)];
        box[k] = Math.min(a, b);
        box[k + 3] = Math.max(a, b);
      }
      // Aimed near the box, so that about half the rays meet it; one ray in four has a zero
      // component (+0 or −0), whose inverse is ±∞.
      const origin = new Vector3(between(-3, 3), between(-3, 3), between(-3, 3));
      const toward = (k: number) => (box[k] + box[k + 3]) / 2 + between(-1, 1) - origin.getComponent(k);
      const component = (k: number) => (i % 4 === 0 && i % 3 === k ? (i % 8 === 0 ? -0 : 0) : toward(k));
      ray.set(origin, new Vector3(component(0), component(1), component(2)).normalize());
      const tMax = i % 5 === 0 ? Infinity : between(0, 4);
      const meets = rayMeetsBox(ray, box, 0, tMax);
      expect(meets).toBe(textbookMeets(ray, box, tMax));
      if (meets) met++;
    }
    expect(met).toBeGreaterThan(2000);
  });

  it('tests the box at its offset in a shared array, and no other', () => {
    const boxes = Float64Array.from([5, 5, 5, 6, 6, 6, -1, -1, -1, 1, 1, 1]);
    const ray = new Ray().set(new Vector3(0, 0, -5), new Vector3(0, 0, 1));
    expect(rayMeetsBox(ray, boxes, 0, Infinity)).toBe(false);
    expect(rayMeetsBox(ray, boxes, 6, Infinity)).toBe(true);
    // Entered at t = 4: not before 3.9, and not from beyond the box (behind the ray).
    expect(rayMeetsBox(ray, boxes, 6, 3.9)).toBe(false);
    expect(rayMeetsBox(new Ray().set(new Vector3(0, 0, 5), new Vector3(0, 0, 1)), boxes, 6, Infinity)).toBe(false);
  });
});
