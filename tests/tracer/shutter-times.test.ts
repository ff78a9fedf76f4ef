import { describe, expect, it } from 'vitest';
import type { TimePattern } from '../../src/scene/scene.ts';
import { shutterTimes } from '../../src/tracer/shutter-times.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { matte, sceneFrom, tracerSceneFrom } from '../support/test-scene.ts';

/** The k shutter times of a pixel sample by the time pattern (distribution-effects §2). */

const K = 4;

function timesOf(pattern: TimePattern, x: number, y: number, sample = 0, k = K, seed = 7): number[] {
  const out = new Array<number>(k);
  shutterTimes(pattern, k, seed, x, y, sample, out);
  return out;
}

/** Pixels (x, y) of an 8×8 block. */
const PIXELS = Array.from({ length: 64 }, (_, i) => [i % 8, Math.floor(i / 8)] as const);

describe('shutter times', () => {
  it('grid: the same moments (i + ½)/k in every pixel and every sample', () => {
    const expected = [0.125, 0.375, 0.625, 0.875];
    for (const [x, y] of PIXELS) expect(timesOf('grid', x, y, (x + y) % 3)).toEqual(expected);
  });

  it('jittered: one moment inside each of the k equal intervals, different from pixel to pixel', () => {
    const seen = new Set<number>();
    for (const [x, y] of PIXELS) {
      const times = timesOf('jittered', x, y);
      times.forEach((time, i) => {
        expect(time).toBeGreaterThanOrEqual(i / K);
        expect(time).toBeLessThan((i + 1) / K);
      });
      seen.add(times[0]);
    }
    expect(seen.size).toBe(PIXELS.length);
  });

  it('random: k moments in [0, 1), not kept to one per interval', () => {
    let clumped = 0;
    for (const [x, y] of PIXELS) {
      const times = timesOf('random', x, y);
      for (const time of times) {
        expect(time).toBeGreaterThanOrEqual(0);
        expect(time).toBeLessThan(1);
      }
      const intervals = new Set(times.map((time) => Math.floor(time * K)));
      if (intervals.size < K) clumped++;
    }
    // Four uniform moments share an interval with probability 1 − 4!/4⁴ ≈ 0.91.
    expect(clumped).toBeGreaterThan(PIXELS.length / 2);
  });

  it('jittered and random draw new moments for another seed or another sample of the pixel; grid does not', () => {
    for (const pattern of ['jittered', 'random'] as const) {
      expect(timesOf(pattern, 2, 3, 0)).not.toEqual(timesOf(pattern, 2, 3, 1));
      expect(timesOf(pattern, 2, 3, 0, K, 7)).not.toEqual(timesOf(pattern, 2, 3, 0, K, 8));
      expect(timesOf(pattern, 2, 3, 1)).toEqual(timesOf(pattern, 2, 3, 1));
    }
    expect(timesOf('grid', 2, 3, 0, K, 7)).toEqual(timesOf('grid', 5, 1, 1, K, 8));
  });

  it('one time sample is τ = 0 in every pattern: the scene as it stands', () => {
    for (const pattern of ['grid', 'jittered', 'random'] as const) expect(timesOf(pattern, 1, 1, 0, 1)).toEqual([0]);
  });
});

describe('the time pattern in a scene', () => {
  it('is jittered when a scene file leaves it out', () => {
    expect(sceneFrom({}).settings.timePattern).toBe('jittered');
  });

  for (const timePattern of ['grid', 'jittered', 'random'] as const) {
    it(`a pixel's ray tree is cast at exactly the moments shutterTimes gives (${timePattern})`, () => {
      const scene = tracerSceneFrom({
        camera: { position: [0, 0.5, 4], target: [0, 0.5, 0], pixels: [4, 3] },
        settings: { timeSamples: K, timePattern, supersampling: 2 },
        objects: [{ id: 'ball', position: [-0.5, 0.5, 0], velocity: [1, 0, 0], material: matte([1, 0, 0]) }],
      });
      for (const [x, y] of [
        [0, 0],
        [2, 1],
        [3, 2],
      ] as const) {
        const trace = tracePixel(scene, x, y, 11);
        trace.rays.forEach((root, sample) => {
          expect(root.children.map((child) => child.time)).toEqual(timesOf(timePattern, x, y, sample, K, 11));
        });
      }
    });
  }
});
