import { describe, expect, it } from 'vitest';
import { estimateRender, HEAVY_RENDER_SECONDS, lighterRenders, modelEstimate } from '../../src/render/render-estimate.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { heaviestScene as heaviest } from '../support/heavy-scenes.ts';
import { sceneFrom } from '../support/test-scene.ts';

/** The rays a real render of `scene` traces. */
function tracedRays(scene: Scene, width: number, height: number): number {
  const stats = emptyRayStats();
  renderTile(buildTracerScene(scene, new Map()), { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 0 }, stats);
  return stats.primary + stats.shadow + stats.reflect + stats.refract;
}

describe('the render estimate', () => {
  it('comes within a factor of three of the rays a render really traces', () => {
    const mirrors = sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, supersampling: 2, maxDepth: 4 } });
    for (const scene of [defaultScene(), mirrors]) {
      const ratio = estimateRender(scene, 64, 48).rays / tracedRays(scene, 64, 48);
      expect(ratio).toBeGreaterThan(1 / 3);
      expect(ratio).toBeLessThan(3);
    }
  });

  it('grows with the pixels and the samples, and shrinks with the workers', () => {
    const scene = defaultScene();
    const base = estimateRender(scene, 100, 100);
    expect(estimateRender(scene, 200, 100).rays).toBeCloseTo(2 * base.rays);
    expect(estimateRender(sceneFrom({ ...scene, settings: { ...scene.settings, supersampling: 3 } }), 100, 100).rays).toBeCloseTo(9 * base.rays);
    expect(estimateRender(scene, 100, 100, 4).seconds).toBeCloseTo(base.seconds / 4);
    expect(base.heavy).toBe(false);
  });

  it('counts lens points, shutter times and glossy rays (distribution-effects §2)', () => {
    const scene = defaultScene();
    const base = estimateRender(scene, 100, 100).rays;
    const lens = sceneFrom({ ...scene, camera: { ...scene.camera, aperture: 0.1, lensSamples: 3 }, settings: { ...scene.settings, timeSamples: 4 } });
    expect(estimateRender(lens, 100, 100).rays).toBeCloseTo(9 * 4 * base);
    // Without an aperture the lens samples cost nothing: every lens ray is the pinhole ray.
    const pinhole = sceneFrom({ ...scene, camera: { ...scene.camera, lensSamples: 3 } });
    expect(estimateRender(pinhole, 100, 100).rays).toBeCloseTo(base);
    const rough = sceneFrom({ ...scene, objects: scene.objects.map((o) => ({ ...o, material: { ...o.material, roughness: 0.3 } })) });
    expect(estimateRender(rough, 100, 100).rays).toBeGreaterThan(5 * base);
    for (const heavier of [lens, rough]) {
      const ratio = estimateRender(heavier, 32, 24).rays / tracedRays(heavier, 32, 24);
      expect(ratio).toBeGreaterThan(1 / 3);
      expect(ratio).toBeLessThan(3);
    }
  });

  it("calls the schema's heaviest scene heavy: weeks, even on eight workers", () => {
    const estimate = estimateRender(heaviest, 4096, 4096, 8);
    expect(estimate.heavy).toBe(true);
    expect(estimate.seconds).toBeGreaterThan(7 * 86_400);
  });

  it('suggests the mildest lighter render of each kind, each under the threshold', () => {
    const scene = sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, supersampling: 8, maxDepth: 6 } });
    const [width, height] = [4096, 4096];
    expect(estimateRender(scene, width, height, 2).heavy).toBe(true);
    const lighter = lighterRenders(scene, width, height, modelEstimate(2));
    expect(lighter.map((option) => option.change)).toEqual(['supersampling', 'image-size', 'max-depth'].slice(0, lighter.length));
    expect(lighter.length).toBeGreaterThanOrEqual(2);
    for (const option of lighter) expect(option.estimate.seconds).toBeLessThanOrEqual(HEAVY_RENDER_SECONDS);
    const samples = lighter.find((option) => option.change === 'supersampling');
    if (samples?.change !== 'supersampling') throw new Error('no fewer-samples suggestion');
    const oneMore = sceneFrom({ ...scene, settings: { ...scene.settings, supersampling: samples.supersampling + 1 } });
    expect(estimateRender(oneMore, width, height, 2).heavy).toBe(true);
    const size = lighter.find((option) => option.change === 'image-size');
    if (size?.change !== 'image-size') throw new Error('no smaller-image suggestion');
    expect(size.width / size.height).toBeCloseTo(1);
    expect(lighterRenders(defaultScene(), 512, 384, modelEstimate(2))).toEqual([]);
  });

  it('in path mode, counts pathSamples × pixels × path length, and suggests fewer paths per pixel, never supersampling', () => {
    const path = (settings: Record<string, unknown>) =>
      sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, integrator: 'path', ...settings } });
    const scene = path({ pathSamples: 4096, maxDepth: 7, supersampling: 4 });
    const [width, height] = [640, 480];
    const full = estimateRender(scene, width, height, 2);
    // Rays of one path at most: (maxDepth + 1) vertices, each its ray and a light sample per light.
    const perPath = 8 * (1 + defaultScene().lights.length);
    expect(full.rays).toBe(4096 * width * height * perPath);
    expect(estimateRender(path({ pathSamples: 1024, maxDepth: 7, supersampling: 4 }), width, height, 2).rays).toBe(full.rays / 4);
    expect(full.heavy).toBe(true);
    const lighter = lighterRenders(scene, width, height, modelEstimate(2));
    expect(lighter.map((option) => option.change)).toEqual(['path-samples', 'image-size', 'max-depth'].slice(0, lighter.length));
    const fewer = lighter[0];
    if (fewer?.change !== 'path-samples') throw new Error('no fewer-paths suggestion');
    expect(fewer.estimate.heavy).toBe(false);
    // The largest power of two that is light enough: twice as many paths would be heavy.
    expect(Math.log2(fewer.pathSamples) % 1).toBe(0);
    expect(estimateRender(path({ pathSamples: 2 * fewer.pathSamples, maxDepth: 7 }), width, height, 2).heavy).toBe(true);
  });
});
