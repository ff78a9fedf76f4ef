import { describe, expect, it } from 'vitest';
import { assignContributions } from '../../src/tracer/ray-contributions.ts';
import type { RayNode, RayType } from '../../src/tracer/ray-tree.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';
import { walkRays } from '../support/ray-fixtures.ts';

function node(type: RayType, color: [number, number, number], children: RayNode[] = []): RayNode {
  return { type, origin: [0, 0, 0], direction: [0, 0, 1], length: 1, hit: true, objectId: null, lightId: null, color, contribution: 0, children };
}

const areaLight = (samples: number, extra: Record<string, unknown> = {}) => ({
  id: 'panel',
  type: 'area',
  position: [0, 3, 0],
  rotation: [0, 0, 0],
  size: [1, 1],
  samples,
  angleAttenuation: 0,
  shape: 'rectangle',
  color: [1, 1, 1],
  intensity: 1,
  ambient: 0,
  diffuse: 1,
  specular: 0,
  distanceAttenuation: false,
  ...extra,
});

/** A scene with every feature whose randomness or recursion could make a tree disagree with the image. */
function busyScene(supersampling: number, samplePattern: string): TracerScene {
  return tracerSceneFrom({
    camera: { position: [0, 1.2, 4], target: [0, 0.4, 0], fov: 50, pixels: [8, 6] },
    settings: { supersampling, samplePattern, maxDepth: 4, background: [0.6, 0.7, 0.9] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([0.8, 0.8, 0.8], { ambient: 0.1, specular: 0.2 }) },
      { id: 'glass', shape: 'sphere', position: [0.3, 0.5, 0.5], material: matte([1, 1, 1], { transparent: true, diffuse: 0.1 }) },
      { id: 'mirror', shape: 'box', position: [-0.8, 0.5, -0.5], rotation: [0, 30, 0], material: matte([0.2, 0.2, 0.2], { specular: 0.8 }) },
      { id: 'pillar', shape: 'cylinder', position: [1.2, 0.5, -0.8], material: matte([0.1, 0.8, 0.3], { specular: 0.3, shininess: 8 }) },
    ],
    lights: [areaLight(3, { rotation: [10, 0, 0] }), pointLight([2, 3, 2], { id: 'bulb', intensity: 0.5 })],
  });
}

describe('ray contributions (spec §3)', () => {
  it('the spec example: a 25% ray whose children give 40% and 20% of its colour has children of 10% and 5%', () => {
    const light = node('light', [0.2, 0.2, 0.2]); // 0.6 of the parent's 1.5: 40%
    const mirror = node('reflect', [0.3, 0.3, 0.3]); // weighted by ks = 0.5: 0.45 of 1.5 would be 30%; see below
    const parent = node('primary', [0.5, 0.5, 0.5], [light, mirror]);
    const others = [node('primary', [1, 1, 1]), node('primary', [1, 1, 1]), node('primary', [1, 1, 1])];
    // ks = 1/3 makes the mirror add 0.3 of 1.5: 20%.
    assignContributions([parent, ...others], new Map([[mirror, 1 / 3]]));
    expect(parent.contribution).toBeCloseTo(0.25, 12);
    expect(light.contribution).toBeCloseTo(0.1, 12);
    expect(mirror.contribution).toBeCloseTo(0.05, 12);
  });

  it('children of a black ray, and blocked shadow rays, contribute 0', () => {
    const shadow = node('shadow', [0, 0, 0]);
    const child = node('reflect', [1, 1, 1]);
    const black = node('primary', [0, 0, 0], [child, shadow]);
    assignContributions([black], new Map());
    expect(black.contribution).toBe(1);
    expect(child.contribution).toBe(0);
    expect(shadow.contribution).toBe(0);
  });
});

describe('pixel ray trees', () => {
  for (const [s, pattern] of [
    [1, 'grid'],
    [2, 'jittered'],
    [3, 'random'],
  ] as const) {
    it(`trace(pixel).color equals the rendered image at the camera's resolution (s = ${s}, ${pattern})`, () => {
      const scene = busyScene(s, pattern);
      const [width, height] = scene.source.camera.pixels;
      const image = renderTile(scene, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 7 });
      for (let y = 0; y < height; y++) {
        for (let x = 0; x < width; x++) {
          const trace = tracePixel(scene, x, y, 7);
          expect(trace.pixel).toEqual([x, y]);
          expect(trace.rays).toHaveLength(s * s);
          expect(trace.color).toEqual(Array.from(image.subarray((y * width + x) * 3, (y * width + x) * 3 + 3)));
        }
      }
    });
  }

  it('roots have 1/s² each; every node follows the contribution rule; shadow rays carry black', () => {
    const trace = tracePixel(busyScene(2, 'grid'), 4, 4, 1);
    for (const root of trace.rays) expect(root.contribution).toBeCloseTo(0.25, 12);
    walkRays(trace.rays, (n) => {
      expect(n.contribution).toBeGreaterThanOrEqual(0);
      if (n.type === 'shadow') {
        expect(n.color).toEqual([0, 0, 0]);
        expect(n.contribution).toBe(0);
      }
      if (!n.hit) expect(n.length).toBe(10);
    });
    const types = new Set<string>();
    walkRays(trace.rays, (n) => types.add(n.type));
    // This pixel looks into the glass sphere: its tree has every kind of ray.
    expect([...types].sort()).toEqual(['light', 'primary', 'reflect', 'refract', 'shadow']);
  });

  it('counts the same rays the tree shows', () => {
    const scene = busyScene(1, 'grid');
    const stats = emptyRayStats();
    renderTile(scene, { x: 3, y: 2, width: 1, height: 1 }, { imageWidth: 8, imageHeight: 6, seed: 1 }, stats);
    const counted = { primary: 0, shadow: 0, reflect: 0, refract: 0 };
    walkRays(tracePixel(scene, 3, 2, 1).rays, (n) => {
      if (n.type === 'light' || n.type === 'shadow') counted.shadow++;
      else counted[n.type as 'primary' | 'reflect' | 'refract']++;
    });
    expect(stats).toEqual(counted);
  });
});

describe('area-ray merging (spec §3)', () => {
  const lit = (samples: number, objects: unknown[] = []) =>
    tracerSceneFrom({
      camera: { position: [0, 2, 3], target: [0, 0, 0], pixels: [1, 1] },
      objects: [{ id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([1, 1, 1]) }, ...objects],
      lights: [areaLight(samples)],
    });
  const lightRays = (scene: TracerScene) => tracePixel(scene, 0, 0, 1).rays[0].children;

  it('25 or more samples that all reach the light become one area-light cone with 4 corners', () => {
    const rays = lightRays(lit(5));
    expect(rays).toHaveLength(1);
    expect(rays[0].type).toBe('area-light');
    expect(rays[0].lightId).toBe('panel');
    expect(rays[0].corners).toHaveLength(4);
    expect(rays[0].corners).toContainEqual([-0.5, 3, -0.5]);
  });

  it('fewer than 25 samples stay separate', () => {
    expect(lightRays(lit(4)).map((r) => r.type)).toEqual(Array(16).fill('light'));
  });

  it('all samples blocked become one area-shadow cone; a mix stays per sample', () => {
    const roof = { id: 'roof', shape: 'box', position: [0, 1.5, 0], scale: [4, 0.1, 4], material: matte([1, 1, 1]) };
    const shadowRays = lightRays(lit(5, [roof]));
    expect(shadowRays.map((r) => r.type)).toEqual(['area-shadow']);
    const edge = { id: 'edge', shape: 'box', position: [0.5, 1.5, 0], scale: [1, 0.1, 4], material: matte([1, 1, 1]) };
    const mixed = lightRays(lit(5, [edge]));
    expect(mixed).toHaveLength(25);
    expect(new Set(mixed.map((r) => r.type))).toEqual(new Set(['light', 'shadow']));
  });
});

describe('what a recorded tree adds to the rays (the lab draws it)', () => {
  const dot = (a: readonly number[], b: readonly number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

  it('every hit of a primary, reflected or refracted ray records its unit normal, turned toward the ray', () => {
    const scene = busyScene(2, 'grid');
    const glass = scene.source.objects.find((object) => object.id === 'glass')!.position;
    let checked = 0;
    let onGlass = 0;
    for (const [x, y] of [
      [4, 4],
      [2, 3],
      [6, 1],
    ]) {
      walkRays(tracePixel(scene, x, y, 1).rays, (n) => {
        const surfaceRay = n.type === 'primary' || n.type === 'reflect' || n.type === 'refract';
        if (!surfaceRay || !n.hit) {
          expect(n.normal).toBeUndefined();
          return;
        }
        const normal = n.normal!;
        expect(Math.hypot(...normal)).toBeCloseTo(1, 6);
        expect(dot(normal, n.direction)).toBeLessThan(0);
        if (n.objectId === 'floor') expect(normal.map((c) => Math.abs(c))).toEqual([0, 1, 0]);
        if (n.objectId === 'glass') {
          // A sphere's normal is along centre → hit point: outward for a ray from outside, inward for one inside.
          const hit = n.origin.map((o, axis) => o + n.length * n.direction[axis]);
          const out = hit.map((h, axis) => h - glass[axis]);
          expect(Math.abs(dot(normal, out)) / Math.hypot(...out)).toBeCloseTo(1, 5);
          onGlass++;
        }
        checked++;
      });
    }
    expect(onGlass).toBeGreaterThan(1);
    expect(checked).toBeGreaterThan(10);
  });

  it('with Shadows off no shadow ray is cast: every ray toward a light is marked untested, merged cones too', () => {
    const roof = { id: 'roof', shape: 'box', position: [0, 1.5, 0], scale: [4, 0.1, 4], material: matte([1, 1, 1]) };
    const lit = (shadows: boolean, samples: number) =>
      tracerSceneFrom({
        camera: { position: [0, 2, 3], target: [0, 0, 0], pixels: [1, 1] },
        settings: { shadows },
        objects: [{ id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([1, 1, 1]) }, roof],
        lights: [areaLight(samples), pointLight([1, 3, 1])],
      });
    const off = tracePixel(lit(false, 5), 0, 0, 1).rays[0].children;
    expect(off.map((r) => [r.type, r.untested])).toEqual([
      ['area-light', true],
      ['light', true],
    ]);
    const stats = emptyRayStats();
    renderTile(lit(false, 2), { x: 0, y: 0, width: 1, height: 1 }, { imageWidth: 1, imageHeight: 1, seed: 1 }, stats);
    expect(stats.shadow).toBe(0);
    const separate = tracePixel(lit(false, 2), 0, 0, 1).rays[0].children;
    expect(separate).toHaveLength(5);
    expect(separate.every((r) => r.type === 'light' && r.untested === true)).toBe(true);
    // With Shadows on the roof blocks both lights, and nothing is marked.
    const on = tracePixel(lit(true, 5), 0, 0, 1).rays[0].children;
    expect(on.map((r) => [r.type, r.untested])).toEqual([
      ['area-shadow', undefined],
      ['shadow', undefined],
    ]);
  });
});
