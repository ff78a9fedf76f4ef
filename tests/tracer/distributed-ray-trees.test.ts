import { describe, expect, it } from 'vitest';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { effectsScene as effectsSceneWith, type EffectsChanges } from '../support/effects-scene.ts';
import { matte } from '../support/test-scene.ts';
import { walkRays } from '../support/ray-fixtures.ts';

/**
 * Ray trees of the distributed effects (distribution-effects §3): lens, glossy and time rays
 * must give each traced pixel exactly its image colour, as the plain rays do (ray-tree.test.ts).
 */

/** The effects scene with a red, glossy ball moving at `velocity`. */
function effectsScene(changes: EffectsChanges & { velocity?: number[] }): TracerScene {
  const ball = {
    id: 'ball',
    shape: 'sphere',
    position: [-0.8, 0.5, -0.3],
    velocity: changes.velocity ?? [0, 0, 0],
    material: matte([0.9, 0.2, 0.1], { specular: 0.5, roughness: changes.rough ?? 0 }),
  };
  return effectsSceneWith([6, 4], changes, [ball]);
}

const cases: [string, Parameters<typeof effectsScene>[0]][] = [
  ['depth of field (aperture 0.2, 3×3 lens points)', { camera: { aperture: 0.2, lensSamples: 3, focusDistance: 3 } }],
  ['depth of field with one lens point', { camera: { aperture: 0.2, lensSamples: 1 } }],
  ['glossy reflection and frosted glass (roughness 0.3)', { rough: 0.3 }],
  ['motion blur (velocity 1 m, 4 times)', { velocity: [1, 0, 0.3], settings: { timeSamples: 4 } }],
  ["motion blur at the grid's fixed times", { velocity: [1, 0, 0.3], settings: { timeSamples: 4, timePattern: 'grid' } }],
  ['motion blur at random times, supersampled', { velocity: [1, 0, 0.3], settings: { timeSamples: 3, timePattern: 'random', supersampling: 2 } }],
  [
    'all three, supersampled',
    { camera: { aperture: 0.1, lensSamples: 2 }, rough: 0.2, velocity: [0.5, 0, 0], settings: { timeSamples: 2, supersampling: 2, samplePattern: 'jittered' } },
  ],
];

describe('distributed ray trees equal the image', () => {
  for (const [name, changes] of cases) {
    it(`trace(pixel).color is the image's colour bit for bit: ${name}`, () => {
      const scene = effectsScene(changes);
      const [width, height] = scene.source.camera.pixels;
      const image = renderTile(scene, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 5 });
      for (let y = 0; y < height; y++) {
        for (let x = 0; x < width; x++) {
          const trace = tracePixel(scene, x, y, 5);
          expect(trace.color).toEqual(Array.from(image.subarray((y * width + x) * 3, (y * width + x) * 3 + 3)));
        }
      }
    });
  }

  it('a root has one primary child per lens point and time, each with its lens point, time and 1/(n²·k) of the root', () => {
    const scene = effectsScene({ camera: { aperture: 0.2, lensSamples: 2 }, settings: { timeSamples: 3 }, velocity: [1, 0, 0] });
    const trace = tracePixel(scene, 2, 2, 1);
    expect(trace.rays).toHaveLength(1);
    const [root] = trace.rays;
    expect(root.children).toHaveLength(2 * 2 * 3);
    const eye = scene.camera.eye.toArray();
    for (const child of root.children) {
      expect(child.type).toBe('primary');
      expect(child.lensPoint).toEqual(child.origin);
      // On the lens disc: within the aperture of the eye, in the plane perpendicular to the view.
      const offset = child.origin.map((c, i) => c - eye[i]);
      expect(Math.hypot(...offset)).toBeLessThanOrEqual(0.2 + 1e-12);
      expect(Math.abs(offset.reduce((sum, c, i) => sum + c * scene.camera.forward.getComponent(i), 0))).toBeLessThan(1e-12);
      expect(child.time).toBeGreaterThanOrEqual(0);
      expect(child.time).toBeLessThan(1);
    }
    // The times are stratified: one in each third of the shutter, the same three for each lens point.
    const times = root.children.slice(0, 3).map((c) => c.time!);
    times.forEach((time, i) => expect(Math.floor(time * 3)).toBe(i));
    // Contributions: each child's share of the root follows its weighted colour; they sum to the root's.
    const sum = (c: number[]) => c[0] + c[1] + c[2];
    const shares = root.children.reduce((total, c) => total + c.contribution, 0);
    expect(shares).toBeCloseTo(root.contribution, 12);
    for (const child of root.children) expect(child.contribution).toBeCloseTo(sum(child.color) / 12 / sum(root.color), 12);
    // Traced with terms, each child carries its weight in the root: 1/(n²·k).
    const weighed = tracePixel(scene, 2, 2, 1, { terms: true }).rays[0];
    expect(weighed.weight).toBe(1);
    expect(weighed.children.map((child) => child.weight)).toEqual(Array(12).fill(1 / 12));
  });

  it("a pinhole with one time keeps today's tree: no lens or time fields, no extra level", () => {
    const trace = tracePixel(effectsScene({}), 2, 2, 1);
    walkRays(trace.rays, (n) => {
      expect(n.lensPoint).toBeUndefined();
      expect(n.time).toBeUndefined();
      expect(n.glossy).toBeUndefined();
    });
    expect(trace.rays[0].children.some((c) => c.type === 'light')).toBe(true);
  });

  it('glossy rays are marked, weigh ks/m² each, and the stats count the rays the tree shows', () => {
    const scene = effectsScene({ rough: 0.3 });
    const trace = tracePixel(scene, 2, 3, 1);
    const glossy: RayNode[] = [];
    walkRays(trace.rays, (n) => n.glossy && glossy.push(n));
    expect(glossy.length).toBeGreaterThan(0);
    expect(glossy.every((n) => n.type === 'reflect' || n.type === 'refract')).toBe(true);
    const stats = emptyRayStats();
    renderTile(scene, { x: 2, y: 3, width: 1, height: 1 }, { imageWidth: 6, imageHeight: 4, seed: 1 }, stats);
    const counted = { primary: 0, shadow: 0, reflect: 0, refract: 0 };
    walkRays(trace.rays, (n) => {
      if (n.absorbed) return; // not traced: no ray is cast into the surface
      if (n.type === 'light' || n.type === 'shadow') counted.shadow++;
      else counted[n.type as 'primary' | 'reflect' | 'refract']++;
    });
    expect(stats).toEqual(counted);
  });

  it('lens and time rays count as primary rays', () => {
    const scene = effectsScene({ camera: { aperture: 0.2, lensSamples: 3 }, settings: { timeSamples: 2 } });
    const stats = emptyRayStats();
    renderTile(scene, { x: 0, y: 0, width: 2, height: 1 }, { imageWidth: 6, imageHeight: 4, seed: 1 }, stats);
    expect(stats.primary).toBe(2 * 3 * 3 * 2);
  });
});
