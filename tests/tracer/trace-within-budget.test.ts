import { describe, expect, it } from 'vitest';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { PixelTrace, RayNode } from '../../src/tracer/ray-tree.ts';
import { tracePixels } from '../../src/tracer/trace-pixel.ts';
import { middleSample, tracePixelsWithinBudget } from '../../src/tracer/trace-within-budget.ts';
import { integratorFor } from '../../src/tracer/render-pixel.ts';
import { buildTracerScene, type TracerScene } from '../../src/tracer/tracer-scene.ts';
import { thinTraces, tracedRays } from '../../src/tracer/tree-budget.ts';
import { effectsScene as effectsSceneWith, type EffectsChanges } from '../support/effects-scene.ts';
import { matte } from '../support/test-scene.ts';

/**
 * The worker's budgeted screen (trace-within-budget.ts) records only the trees the budget
 * keeps; what it sends must be what recording every tree and thinning them sent before
 * (thinTraces over tracePixels), bit for bit: the same trees, colours, shares and counts.
 */

/** The effects scene with a moving mirror ball and a blue block. */
function effectsScene(changes: EffectsChanges): TracerScene {
  return effectsSceneWith([5, 4], changes, [
    { id: 'mirror', shape: 'sphere', position: [-0.8, 0.5, -0.3], velocity: [0.6, 0, 0.2], material: matte([0.9, 0.9, 0.9], { specular: 0.8 }) },
    { id: 'block', shape: 'box', position: [1.3, 0.3, -0.8], scale: [0.6, 0.6, 0.6], material: matte([0.2, 0.4, 0.9]) },
  ]);
}

/** The free lab's scene with its largest settings (1,024 camera rays a pixel) on a screen of `pixels`. */
function largestFreeLab(pixels: [number, number]): TracerScene {
  const scene = defaultScene();
  scene.camera = { ...scene.camera, aperture: 0.2, lensSamples: 4, pixels };
  scene.settings = { ...scene.settings, supersampling: 4, timeSamples: 4 };
  return buildTracerScene(scene, new Map());
}

/** What the worker sent before: every tree recorded, then thinned. */
function recordedThenThinned(scene: TracerScene, first: number, count: number, budget: number, keepPixel: number | null): PixelTrace[] {
  return thinTraces(tracePixels(scene, first, count, 7), budget, keepPixel);
}

const cases: [string, TracerScene][] = [
  ['the free lab’s largest settings (lens, shutter, supersampling)', largestFreeLab([3, 2])],
  ['supersampling alone: a tree per sample, mirror and glass rays below it', effectsScene({ settings: { supersampling: 3 } })],
  ['an area light of 25 samples (one cone when they agree), rough surfaces', effectsScene({ areaSamples: 5, rough: 0.3 })],
  ['shadows off: untested light rays', effectsScene({ areaSamples: 5, settings: { shadows: false, supersampling: 2 } })],
  ['one lens point and one time: the lens ray is the root', effectsScene({ camera: { aperture: 0.2, lensSamples: 1 } })],
  ['lens and shutter, supersampled', effectsScene({ camera: { aperture: 0.1, lensSamples: 2 }, settings: { timeSamples: 3, supersampling: 2 } })],
];

describe('tracePixelsWithinBudget: only the trees a budget keeps are recorded', () => {
  for (const [name, scene] of cases) {
    it(`sends what recording every tree and thinning them sent: ${name}`, () => {
      const [columns, rows] = scene.source.camera.pixels;
      const pixels = columns * rows;
      const recorded = tracePixels(scene, 0, pixels, 7);
      const all = tracedRays(recorded);
      // Budgets from a sliver of the rays to all of them, with and without a chosen pixel.
      for (const [budget, keepPixel] of [
        [Math.ceil(all / 50), null],
        [Math.ceil(all / 7), pixels - 2],
        [all, null],
      ] as const) {
        expect(tracePixelsWithinBudget(scene, 0, pixels, 7, budget, keepPixel)).toEqual(thinTraces(recorded, budget, keepPixel));
      }
      // The budget left rays out (else nothing was tested), and says how many each pixel traced.
      const thin = tracePixelsWithinBudget(scene, 0, pixels, 7, Math.ceil(all / 50), null);
      expect(tracedRays(thin)).toBe(all);
      expect(thin.some((trace) => trace.traced !== undefined)).toBe(true);
    });
  }

  it('traces a block from the middle of the screen, its chosen pixel counted from the block’s first', () => {
    const scene = effectsScene({ camera: { aperture: 0.2, lensSamples: 2 }, settings: { timeSamples: 2 } });
    expect(tracePixelsWithinBudget(scene, 6, 9, 7, 60, 4)).toEqual(recordedThenThinned(scene, 6, 9, 60, 4));
  });

  for (const [name, scene] of [cases[0], cases[1], cases[5]]) {
    it(`traces each pixel but the chosen one from its middle sample alone, uncounted, with oneSample: ${name}`, () => {
      const [columns, rows] = scene.source.camera.pixels;
      const pixels = columns * rows;
      const s = scene.settings.supersampling;
      const middle = middleSample(s);
      const recorded = tracePixels(scene, 0, pixels, 7);
      const keepPixel = pixels - 1;
      // The middle sample's trees of every pixel (the chosen pixel's all), as the whole trace recorded them.
      const ofMiddle = recorded.map((trace, p) => (p === keepPixel ? trace : { ...trace, rays: [trace.rays[middle]] }));
      const budget = Math.ceil(tracedRays(ofMiddle) / 5);
      const expected = thinTraces(ofMiddle, budget, keepPixel).map((trace, p): PixelTrace => {
        if (p === keepPixel) return trace;
        const { traced: _uncounted, ...rest } = trace;
        return { ...rest, color: sampleColor(recorded[p].rays[middle]), onlySample: middle };
      });
      const sent = tracePixelsWithinBudget(scene, 0, pixels, 7, budget, keepPixel, true);
      expect(sent).toEqual(expected);
      expect(sent.filter((trace) => trace.rays.length > 0).length).toBeGreaterThan(1);
      // Without a chosen pixel: the middle samples once (1/s² of the screen's camera rays), then only the kept trees among them again.
      const primary = () => integratorFor(scene).stats.primary;
      const cameraRays = (trace: () => void) => {
        const start = primary();
        trace();
        return primary() - start;
      };
      const whole = cameraRays(() => tracePixels(scene, 0, pixels, 7));
      const fifth = Math.ceil(tracedRays(recorded.map((trace) => ({ ...trace, rays: [trace.rays[middle]] }))) / 5);
      const sampled = cameraRays(() => tracePixelsWithinBudget(scene, 0, pixels, 7, fifth, null, true));
      expect(sampled).toBeGreaterThan(whole / s ** 2);
      expect(sampled).toBeLessThan((2 * whole) / s ** 2);
    });
  }

  it('sends the colours alone in path mode, where a pixel records no tree', () => {
    const scene = effectsScene({ settings: { integrator: 'path', pathSamples: 2 } });
    const sent = tracePixelsWithinBudget(scene, 0, 20, 7, 10, null);
    expect(sent).toEqual(tracePixels(scene, 0, 20, 7));
    expect(sent.every((trace) => trace.rays.length === 0)).toBe(true);
  });
});

/** A sample's colour as a pixel traced from it alone has it: what its root carries (its pinhole ray, or its one camera ray), in 32-bit floats. */
function sampleColor(root: RayNode): [number, number, number] {
  return [Math.fround(root.color[0]), Math.fround(root.color[1]), Math.fround(root.color[2])];
}
