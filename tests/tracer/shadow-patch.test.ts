import { Vector3 } from 'three';
import { describe, expect, it, vi } from 'vitest';
import { objectGridScene } from '../../bench/object-grid-scene.ts';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { hashKey, RandomStream } from '../../src/tracer/sampler.ts';
import { RayCone } from '../../src/tracer/ray-cone.ts';
import { ShadowPatch, ShadowPatchPair } from '../../src/tracer/shadow-patch.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

const random = new RandomStream().reset(hashKey(47));
const between = (low: number, high: number) => low + (high - low) * random.next();
const boxOf = ({ worldBounds: { min, max } }: Intersectable) => new Float64Array([min.x, min.y, min.z, max.x, max.y, max.z]);

// A crowd of 256 objects under an area light: most boxes from a point to the light overlap many.
const scene = buildTracerScene(objectGridScene(16), new Map());
const light = scene.lights.find((l) => l.type === 'area')!;
const margin = 4 * scene.epsilon;
const LIMIT = 1000;

/** The patch's objects (all of them: the limit is set high enough to list every one). */
function patchAround(center: Vector3, half: number): Set<Intersectable> {
  const patch = new ShadowPatch();
  patch.fill(center, half, light, scene.occluders, margin, LIMIT);
  expect(patch.count).toBeGreaterThanOrEqual(0);
  expect(patch.covers(center)).toBe(true);
  return new Set(patch.list.slice(0, patch.count));
}

/** A point of the cube of half-side `half` around `center`: a corner every other time, the worst case. */
function pointIn(center: Vector3, half: number, corner: boolean): Vector3 {
  const offset = () => (corner ? (random.next() < 0.5 ? -half : half) : between(-half, half));
  return new Vector3(center.x + offset(), center.y + offset(), center.z + offset());
}

describe('a shadow patch: one list of shadow candidates for neighbouring hits', () => {
  const top = scene.shapes[8 * 16 + 8].worldBounds;
  const above = new Vector3((top.min.x + top.max.x) / 2, top.max.y + 0.01, (top.min.z + top.max.z) / 2);

  it("lists every object a point of its cube would list, so each hit's shadow rays test all they must", () => {
    const cone = new RayCone();
    let compared = 0;
    for (let trial = 0; trial < 40; trial++) {
      // Among the objects (where a floor's hits would be) and above them.
      const center = above.clone().add(new Vector3(between(-2, 2), between(top.min.y - top.max.y, 0.5), between(-2, 2)));
      const half = between(0.005, 0.2);
      const listed = patchAround(center, half);
      for (let k = 0; k < 10; k++) {
        const point = pointIn(center, half, k % 2 === 0);
        expect(Math.max(Math.abs(point.x - center.x), Math.abs(point.y - center.y), Math.abs(point.z - center.z))).toBeLessThanOrEqual(half * (1 + 1e-12));
        // What the integrator lists for this one hit: the box from it to the light, cut by its cone.
        const reach = light.extent.clone().expandByPoint(point);
        cone.toLight(point, light, margin);
        for (const shape of scene.shapes) {
          if (!shape.worldBounds.intersectsBox(reach) || cone.excludes(boxOf(shape), 0)) continue;
          expect(listed.has(shape)).toBe(true);
          compared++;
        }
      }
    }
    expect(compared).toBeGreaterThan(100);
  });

  it('holds every object that really blocks a shadow ray from a point of its cube', () => {
    const sample = new Vector3();
    const ray = new Ray();
    let blocked = 0;
    for (let trial = 0; trial < 40; trial++) {
      const center = above.clone().add(new Vector3(between(-2, 2), between(0, 0.5), between(-2, 2)));
      const half = 0.1;
      const listed = patchAround(center, half);
      for (let k = 0; k < 20; k++) {
        const point = pointIn(center, half, k % 2 === 0);
        light.samplePoint(k % light.samplesPerSide, Math.floor(k / light.samplesPerSide) % light.samplesPerSide, random, sample);
        const toLight = sample.clone().sub(point);
        const distance = toLight.length();
        ray.set(point, toLight.normalize());
        ray.far = distance - scene.epsilon;
        for (const shape of scene.shapes) {
          if (!shape.occludes(ray)) continue;
          expect(listed.has(shape)).toBe(true);
          blocked++;
        }
      }
    }
    expect(blocked).toBeGreaterThan(20);
  });

  it('covers the points of its cube only, and none before it is filled', () => {
    const patch = new ShadowPatch();
    expect(patch.covers(above)).toBe(false);
    patch.fill(above, 0.1, light, scene.occluders, margin, LIMIT);
    expect(patch.covers(above.clone().add(new Vector3(0.1, -0.1, 0.1)))).toBe(true);
    expect(patch.covers(above.clone().add(new Vector3(0.1001, 0, 0)))).toBe(false);
  });

  it('says when there are more objects than are worth listing', () => {
    const patch = new ShadowPatch();
    patch.fill(above, 0.5, light, scene.occluders, margin, 2);
    expect(patch.count).toBe(-1);
  });

  it('keeps two patches, so that hits alternating between two places are listed once each', () => {
    const pair = new ShadowPatchPair();
    const upper = above.clone();
    const lower = above.clone().add(new Vector3(0, 0, 0.5));
    let fills = 0;
    const fill = ShadowPatch.prototype.fill;
    const spy = vi.spyOn(ShadowPatch.prototype, 'fill').mockImplementation(function (this: ShadowPatch, ...args) {
      fills++;
      fill.apply(this, args);
    });
    const listFor = (point: Vector3) => pair.listFor(point, 0.1, light, scene.occluders, margin, LIMIT);
    // Two rows of hits, as a pixel's supersamples on a floor far apart in depth.
    for (let sample = 0; sample < 8; sample++) {
      const point = sample % 2 === 0 ? upper : lower;
      expect(listFor(point).covers(point)).toBe(true);
    }
    expect(fills).toBe(2);
    // A third place takes the patch used less recently (the upper one); the lower one stays.
    const third = above.clone().add(new Vector3(1, 0, 0));
    const replaced = listFor(third);
    expect(replaced.covers(upper)).toBe(false);
    expect(replaced.covers(third)).toBe(true);
    expect(listFor(lower).covers(lower)).toBe(true);
    expect(fills).toBe(3);
    expect(listFor(upper).covers(upper)).toBe(true);
    expect(fills).toBe(4);
    spy.mockRestore();
  });
});
