import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { perpendicularBasis } from '../../src/tracer/glossy.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { matte, pointLight, tracerSceneFrom } from '../support/test-scene.ts';
import { walkRays } from '../support/ray-fixtures.ts';

/** Glossy reflection and frosted glass (distribution-effects §2). */

const W = 48;
const H = 36;

/** A mirror floor under a red ball, with the floor's and a glass ball's roughness ρ and m. */
function mirrorScene(roughness: number, glossySamples = 3) {
  return tracerSceneFrom({
    camera: { position: [0, 1, 4], target: [0, 0.3, 0], fov: 45, pixels: [8, 6] },
    settings: { background: [0.3, 0.5, 0.8] },
    objects: [
      { id: 'floor', shape: 'plane', scale: [10, 1, 10], material: matte([0.2, 0.2, 0.2], { specular: 0.8, roughness, glossySamples }) },
      { id: 'ball', shape: 'sphere', position: [0, 0.6, 0], material: matte([0.9, 0.1, 0.1]) },
      { id: 'glass', shape: 'sphere', position: [1, 0.5, 1], material: matte([1, 1, 1], { transparent: true, diffuse: 0, roughness, glossySamples }) },
    ],
    lights: [pointLight([2, 3, 3])],
  });
}

const render = (scene: ReturnType<typeof mirrorScene>) => renderTile(scene, { x: 0, y: 0, width: W, height: H }, { imageWidth: W, imageHeight: H, seed: 4 });

function maxDifference(a: Float32Array, b: Float32Array): number {
  return a.reduce((worst, value, i) => Math.max(worst, Math.abs(value - b[i])), 0);
}

describe('glossy reflection', () => {
  it('the basis around R is orthonormal for any direction, also straight down −z', () => {
    const t = new Vector3();
    const b = new Vector3();
    for (const r of [
      [0, 0, -1],
      [0, 0, 1],
      [0.3, -0.4, 0.866],
      [1, 0, 0],
      [-0.6, 0.8, 0],
    ]) {
      const rv = new Vector3(...r).normalize();
      perpendicularBasis(rv, t, b);
      expect(t.length()).toBeCloseTo(1, 12);
      expect(b.length()).toBeCloseTo(1, 12);
      expect(t.dot(rv)).toBeCloseTo(0, 12);
      expect(b.dot(rv)).toBeCloseTo(0, 12);
      expect(t.dot(b)).toBeCloseTo(0, 12);
    }
  });

  it('a spread of 0 is the mirror, bit for bit, whatever the glossy samples', () => {
    const mirror = render(mirrorScene(0, 1));
    expect(render(mirrorScene(0, 8))).toEqual(mirror);
    const trace = tracePixel(mirrorScene(0, 8), 4, 5, 1);
    walkRays(trace.rays, (n) => expect(n.glossy).toBeUndefined());
  });

  it('a vanishing spread converges to the mirror; a real one blurs it', () => {
    const mirror = render(mirrorScene(0));
    expect(maxDifference(render(mirrorScene(1e-9, 2)), mirror)).toBeLessThan(1e-6);
    expect(maxDifference(render(mirrorScene(0.4, 2)), mirror)).toBeGreaterThan(0.05);
  });

  it('m×m glossy rays leave within atan(ρ) of the mirror direction, each weighing ks/m²', () => {
    const roughness = 0.3;
    // Pixel 4,5 looks at the floor just in front of the ball.
    const [root] = tracePixel(mirrorScene(roughness, 4), 4, 5, 1).rays;
    expect(root.objectId).toBe('floor');
    const d = new Vector3(...root.direction);
    const mirrorDirection = d.clone().reflect(new Vector3(0, 1, 0));
    const glossy = root.children.filter((c) => c.type === 'reflect');
    expect(glossy).toHaveLength(16);
    const sum = (c: number[]) => c[0] + c[1] + c[2];
    for (const ray of glossy) {
      expect(ray.glossy).toBe(true);
      const angle = new Vector3(...ray.direction).angleTo(mirrorDirection);
      expect(angle).toBeLessThanOrEqual(Math.atan(roughness) + 1e-9);
      expect(ray.contribution).toBeCloseTo((root.contribution * (0.8 / 16) * sum(ray.color)) / sum(root.color), 12);
    }
    // The spread is real: not all rays go the same way.
    const spreadAngles = glossy.map((ray) => new Vector3(...ray.direction).angleTo(mirrorDirection));
    expect(Math.max(...spreadAngles)).toBeGreaterThan(Math.atan(roughness) / 2);
  });

  it('a glossy ray pointing into the surface is absorbed: black, length 0, not traced', () => {
    // A grazing view of a very rough floor: part of the spread dips below the floor.
    const scene = tracerSceneFrom({
      camera: { position: [0, 0.2, 4], target: [0, 0, 0], fov: 30, pixels: [1, 1] },
      settings: { background: [1, 1, 1] },
      objects: [{ id: 'floor', shape: 'plane', scale: [20, 1, 20], material: matte([0, 0, 0], { specular: 1, roughness: 1, glossySamples: 4 }) }],
    });
    const [root] = tracePixel(scene, 0, 0, 1).rays;
    const absorbed = root.children.filter((c) => c.absorbed);
    expect(absorbed.length).toBeGreaterThan(0);
    expect(absorbed.length).toBeLessThan(16);
    for (const ray of absorbed) {
      expect(ray.direction[1]).toBeLessThanOrEqual(0);
      expect(ray.length).toBe(0);
      expect(ray.color).toEqual([0, 0, 0]);
      expect(ray.contribution).toBe(0);
      expect(ray.children).toEqual([]);
    }
    // The others see the white sky: the floor is exactly as bright as the share that got out.
    const out = 16 - absorbed.length;
    expect(root.color[0]).toBeCloseTo(out / 16, 12);
  });

  it('frosted glass spreads both its refracted and its reflected rays', () => {
    const scene = mirrorScene(0.2, 2);
    const roots = Array.from({ length: 48 }, (_, p) => tracePixel(scene, p % 8, Math.floor(p / 8), 1).rays[0]);
    const root = roots.find((r) => r.objectId === 'glass');
    if (!root) throw new Error('no pixel looks at the glass ball');
    const kinds = root.children.filter((c) => c.glossy).map((c) => c.type);
    expect(kinds.filter((k) => k === 'refract')).toHaveLength(4);
    expect(kinds.filter((k) => k === 'reflect')).toHaveLength(4);
  });
});
