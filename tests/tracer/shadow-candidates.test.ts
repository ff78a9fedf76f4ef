import { Vector3 } from 'three';
import { afterEach, describe, expect, it, vi } from 'vitest';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import { Ray } from '../../src/tracer/ray.ts';
import { integratorFor } from '../../src/tracer/render-pixel.ts';
import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

/**
 * The shadow rays of one hit toward an area light test only the objects listed for that
 * hit (those in the pyramid from the point to the light): the light's last blocker first,
 * and no ray at all when the list holds nothing but the surface the rays leave.
 */
const SAMPLES = 16;

function sceneWithBlockers(): TracerScene {
  return tracerSceneFrom({
    settings: { background: [0, 0, 0], shadows: true },
    objects: [
      { id: 'floor', shape: 'plane', scale: [20, 1, 20], material: matte([1, 1, 1]) },
      // A speck inside the pyramid from (1, 0, 0) to the light that no shadow ray meets.
      { id: 'speck', shape: 'box', position: [1.3, 2.5, 0.3], scale: [0.001, 0.001, 0.001], material: matte([1, 0, 0]) },
      // Covers the light as seen from (1, 0, 0) and the points near it.
      { id: 'roof', shape: 'box', position: [1, 1, 0], scale: [1, 0.1, 1], material: matte([0, 1, 0]) },
    ],
    lights: [{ id: 'panel', type: 'area', position: [1, 3, 0], size: [0.8, 0.8], samples: 4, ambient: 0, angleAttenuation: 0 }],
  });
}

/** Counts each shape's any-hit tests from here on. */
function countOccludes(scene: TracerScene): Map<string, number> {
  const counts = new Map<string, number>();
  for (const shape of scene.shapes) {
    const occludes = shape.occludes.bind(shape);
    vi.spyOn(shape as Intersectable, 'occludes').mockImplementation((ray) => {
      counts.set(shape.id, (counts.get(shape.id) ?? 0) + 1);
      return occludes(ray);
    });
  }
  return counts;
}

/** Shades the floor point (x, 0, z), seen straight from above. */
function shadeFloor(scene: TracerScene, x: number, z: number): number[] {
  const integrator = integratorFor(scene);
  integrator.startPixelSample(7, Math.round(x * 100), Math.round(z * 100), 0);
  const ray = new Ray().set(new Vector3(x, 0.05, z), new Vector3(0, -1, 0));
  return integrator.li(ray, new Vector3(), null).toArray();
}

afterEach(() => vi.restoreAllMocks());

describe('shadow rays toward an area light', () => {
  it('try the object that blocked the last one first', () => {
    const scene = sceneWithBlockers();
    const counts = countOccludes(scene);
    expect(shadeFloor(scene, 1, 0)).toEqual([0, 0, 0]);
    // The first ray tries the speck, then the roof blocks it; the other 15 try the roof alone.
    expect(counts.get('speck')).toBe(1);
    expect(counts.get('roof')).toBe(SAMPLES);
    counts.clear();
    // A neighbouring point: the roof, the light's last blocker, is tried first at once.
    expect(shadeFloor(scene, 1.05, 0.05)).toEqual([0, 0, 0]);
    expect(counts.get('speck')).toBeUndefined();
    expect(counts.get('roof')).toBe(SAMPLES);
  });

  it('test nothing, and set up no ray, where no listed object can block them', () => {
    const scene = sceneWithBlockers();
    shadeFloor(scene, 1, 0); // the roof becomes the light's last blocker
    const counts = countOccludes(scene);
    const raySet = vi.spyOn(Ray.prototype, 'set');
    const { stats } = integratorFor(scene);
    const before = stats.shadow;
    // Far from the roof: the light is in full view, and only the floor itself is listed.
    const color = shadeFloor(scene, -4, 3);
    expect(color[0]).toBeGreaterThan(0);
    expect(stats.shadow - before).toBe(SAMPLES);
    expect([...counts.values()]).toEqual([]);
    // The primary ray only.
    expect(raySet).toHaveBeenCalledTimes(1);
  });

  it("still test the hit's own shape when a ray can meet it again (a model shadowing itself)", () => {
    // A model (in the place of the prism): a floor square at y = 0 and a roof square at y = 1 above it.
    const square = (y: number) => [-1, y, -1, 1, y, -1, 1, y, 1, -1, y, 1];
    const model = {
      positions: new Float32Array([...square(0), ...square(1)]),
      normals: null,
      indices: new Uint32Array([0, 2, 1, 0, 3, 2, 4, 6, 5, 4, 7, 6]),
    };
    const scene = tracerSceneFrom(
      {
        settings: { background: [0, 0, 0], shadows: true },
        objects: [{ id: 'shed', shape: 'mesh', mesh: 'prism', material: matte([1, 1, 1]) }],
        lights: [{ id: 'panel', type: 'area', position: [0, 3, 0], size: [0.5, 0.5], samples: 4, ambient: 0, angleAttenuation: 0 }],
      },
      new Map([['prism', model]]),
    );
    const counts = countOccludes(scene);
    expect(shadeFloor(scene, 0.1, 0.1)).toEqual([0, 0, 0]);
    expect(counts.get('shed')).toBe(SAMPLES);
  });

  it('are blocked without a test inside a convex object, unless the light is inside it too', () => {
    // A ball of radius 1 around (0, 1, 0), seen from its centre: the ray hits the inside of its bottom.
    const ballWithLightAt = (y: number, size: number) =>
      tracerSceneFrom({
        settings: { background: [0, 0, 0], shadows: true },
        objects: [{ id: 'ball', shape: 'sphere', position: [0, 1, 0], scale: [2, 2, 2], material: matte([1, 1, 1]) }],
        lights: [{ id: 'panel', type: 'area', position: [0, y, 0], size: [size, size], samples: 4, ambient: 0, angleAttenuation: 0 }],
      });
    const shadeInside = (scene: TracerScene) => {
      const integrator = integratorFor(scene);
      integrator.startPixelSample(7, 0, 0, 0);
      const before = integrator.stats.shadow;
      const color = integrator.li(new Ray().set(new Vector3(0, 1, 0), new Vector3(0, -1, 0)), new Vector3(), null).toArray();
      return { color, shadowRays: integrator.stats.shadow - before };
    };
    // The light above the ball: every ray meets the ball's top on its way.
    const outside = ballWithLightAt(4, 0.5);
    const outsideCounts = countOccludes(outside);
    expect(shadeInside(outside)).toEqual({ color: [0, 0, 0], shadowRays: SAMPLES });
    expect(outsideCounts.get('ball')).toBeUndefined();
    // The light inside the ball: the rays reach it, so each is tested.
    const inside = ballWithLightAt(1.5, 0.2);
    const insideCounts = countOccludes(inside);
    const lit = shadeInside(inside);
    expect(lit.shadowRays).toBe(SAMPLES);
    expect(lit.color[0]).toBeGreaterThan(0);
    expect(insideCounts.get('ball')).toBe(SAMPLES);
  });

  it('are tested from behind a plane, which has no inside', () => {
    // A ceiling at y = 1 facing up, seen from below, with the light below it too: the rays reach the light.
    const scene = tracerSceneFrom({
      settings: { background: [0, 0, 0], shadows: true },
      objects: [{ id: 'ceiling', shape: 'plane', position: [0, 1, 0], scale: [20, 1, 20], material: matte([1, 1, 1]) }],
      lights: [{ id: 'panel', type: 'area', position: [0, -2, 0], rotation: [180, 0, 0], size: [0.5, 0.5], samples: 4, ambient: 0, angleAttenuation: 0 }],
    });
    const integrator = integratorFor(scene);
    integrator.startPixelSample(7, 0, 0, 0);
    const color = integrator.li(new Ray().set(new Vector3(0, 0, 0), new Vector3(0, 1, 0)), new Vector3(), null).toArray();
    expect(integrator.stats.shadow).toBe(SAMPLES);
    expect(color[0]).toBeGreaterThan(0);
  });
});
