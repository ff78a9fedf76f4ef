import { describe, expect, it } from 'vitest';
import { measuredEstimate, type SampleCost } from '../../src/render/measured-estimate.ts';
import { HEAVY_RENDER_SECONDS, lighterRenders } from '../../src/render/render-estimate.ts';
import { raysOf } from '../../src/render/render-work.ts';
import { EstimateCalibration } from '../../src/render/estimate-calibration.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { sceneFrom } from '../support/test-scene.ts';

const lab = defaultScene();
const withSettings = (scene: Scene, settings: Partial<Scene['settings']>): Scene => sceneFrom({ ...scene, settings: { ...scene.settings, ...settings } });

/** 2 ms (of wall time, all workers) and 40 rays a sample. */
const cost: SampleCost = { samples: 1000, rays: 40_000, ms: 2000 };

describe('the estimate from a probe of the scene', () => {
  it("prices every sample of every pass at the probe's wall ms per sample, times the session's correction", () => {
    const scene = withSettings(lab, { supersampling: 1 });
    const once = measuredEstimate(cost, scene, { workers: 2, preview: false, correction: 1 });
    // Without previews, a 100 × 100 image at one sample per pixel is 10,000 samples: 20 s.
    expect(once(scene, 100, 100).seconds).toBeCloseTo(20);
    expect(once(scene, 100, 100).rays).toBeCloseTo(400_000);
    expect(measuredEstimate(cost, scene, { workers: 2, preview: false, correction: 1.5 })(scene, 100, 100).seconds).toBeCloseTo(30);
    // Supersampling 3 is 9 samples per pixel, each costing what a probe sample did.
    expect(once(withSettings(lab, { supersampling: 3 }), 100, 100).seconds).toBeCloseTo(180);
    expect(once(scene, 200, 100).seconds).toBeCloseTo(40);
  });

  it("counts the rays of all path mode's refining passes as the image's, and every path's time", () => {
    const scene = withSettings(lab, { integrator: 'path', pathSamples: 64 });
    const inWindow = measuredEstimate(cost, scene, { workers: 2, preview: true, correction: 1 })(scene, 320, 240);
    const oneShot = measuredEstimate(cost, scene, { workers: 2, preview: false, correction: 1 })(scene, 320, 240);
    expect(inWindow.rays).toBeCloseTo(64 * 320 * 240 * 40);
    expect(oneShot.rays).toBeCloseTo(inWindow.rays);
    // The window adds only its coarse previews, a few percent of one path per pixel.
    expect(inWindow.seconds).toBeGreaterThan(oneShot.seconds);
    expect(inWindow.seconds).toBeLessThan(oneShot.seconds * (1 + 1 / 64));
  });

  it('adds the previews and the sharp pass of the render window to the final pass', () => {
    const scene = withSettings(lab, { supersampling: 2 });
    const estimate = (preview: boolean) => measuredEstimate(cost, scene, { workers: 2, preview, correction: 1 })(scene, 512, 384).seconds;
    // With 2×2 samples a pixel: the sharp pass is a quarter of the final one, the 8×8 and 4×4 previews 1/64 and 1/16 of the sharp one.
    expect(estimate(true) / estimate(false)).toBeCloseTo(1 + (1 + 1 / 64 + 1 / 16) / 4, 3);
  });

  it("prices a shallower ray tree by the model's ratio of rays per sample, the one part not measured", () => {
    const deep = withSettings(lab, { maxDepth: 6 });
    const estimate = measuredEstimate(cost, deep, { workers: 2, preview: true, correction: 1 });
    expect(estimate(withSettings(deep, { maxDepth: 0 }), 256, 256).seconds).toBeLessThan(estimate(deep, 256, 256).seconds);
  });

  it('sizes the lighter image to the minute, and calls the renders over it heavy', () => {
    const scene = withSettings(lab, { supersampling: 4 });
    const estimate = measuredEstimate(cost, scene, { workers: 2, preview: true, correction: 1 });
    expect(estimate(scene, 1024, 768).heavy).toBe(true);
    const smaller = lighterRenders(scene, 1024, 768, estimate).find((option) => option.change === 'image-size');
    if (smaller?.change !== 'image-size') throw new Error('no smaller image suggested');
    expect(smaller.estimate.seconds).toBeLessThanOrEqual(HEAVY_RENDER_SECONDS);
    expect(smaller.estimate.seconds).toBeGreaterThan(0.95 * HEAVY_RENDER_SECONDS);
    expect(smaller.width / smaller.height).toBeCloseTo(1024 / 768, 1);
  });

  /** Rays of a render of `scene` at `samplesPerPixel`, traced here. */
  function raysOfRender(scene: Scene, width: number, height: number, samplesPerPixel: number): number {
    const stats = emptyRayStats();
    renderTile(buildTracerScene(scene, new Map()), { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 0, samplesPerPixel }, stats);
    return raysOf(stats);
  }

  it('predicts the rays of renders with lens, area-light, glossy and supersampled samples within 10 %, from a probe of a sixteenth of the pixels', () => {
    const areaLight = { id: 'panel', type: 'area', position: [0, 3, 1], size: [1, 1], samples: 3 };
    const scenes: Record<string, Scene> = {
      'lens and area light': sceneFrom({ ...lab, camera: { ...lab.camera, aperture: 0.2, lensSamples: 3 }, lights: [areaLight] }),
      glossy: sceneFrom({ ...lab, objects: lab.objects.map((o) => ({ ...o, material: { ...o.material, roughness: 0.3, glossySamples: 3, specular: 0.6 } })) }),
      supersampled: withSettings(lab, { supersampling: 3, maxDepth: 4 }),
    };
    const [width, height] = [64, 48];
    for (const [name, scene] of Object.entries(scenes)) {
      const probe = { samples: (width / 4) * (height / 4), rays: raysOfRender(scene, width / 4, height / 4, 1), ms: 1 };
      const estimated = measuredEstimate(probe, scene, { workers: 1, preview: false, correction: 1 })(scene, width, height).rays;
      const real = raysOfRender(scene, width, height, scene.settings.supersampling ** 2);
      expect(estimated / real, name).toBeGreaterThan(0.9);
      expect(estimated / real, name).toBeLessThan(1.1);
    }
  });
});

describe("the correction from this session's renders", () => {
  it('is 1 before any render, and leaves out renders estimated at under 5 s', () => {
    const calibration = new EstimateCalibration();
    expect(calibration.correction).toBe(1);
    calibration.record(4, 12_000);
    expect(calibration.correction).toBe(1);
  });

  it('is the real time per estimated time of the renders recorded and a prior minute that came out as estimated, the longest weighing most', () => {
    const calibration = new EstimateCalibration();
    calibration.record(60, 30_000);
    // One render of a minute that took half: halfway there.
    expect(calibration.correction).toBeCloseTo(90 / 120);
    calibration.record(10, 20_000);
    calibration.record(90, 100_000);
    expect(calibration.correction).toBeCloseTo((60 + 150) / (60 + 160));
    for (let i = 0; i < 50; i++) calibration.record(60, 90_000);
    expect(calibration.correction).toBeGreaterThan(1.45);
  });

  it('stays within a factor 3 either way', () => {
    const slow = new EstimateCalibration();
    slow.record(10, 6_000_000);
    expect(slow.correction).toBe(3);
    const fast = new EstimateCalibration();
    for (let i = 0; i < 20; i++) fast.record(60, 1000);
    expect(fast.correction).toBeCloseTo(1 / 3);
  });
});
