import { describe, expect, it } from 'vitest';
import { estimateRender } from '../../src/render/render-estimate.ts';
import { SINGLE_WORKER_SECONDS, workersWorthStarting } from '../../src/cli/workers-worth-starting.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';

const scene = defaultScene();
const estimate = (side: number) => estimateRender(scene, side, side, 1).seconds;
/** The side of the largest square image whose one-worker estimate is under SINGLE_WORKER_SECONDS. */
const largestSmall = Math.floor(Math.sqrt(SINGLE_WORKER_SECONDS / estimate(1)) - 1e-9);

describe('the workers rt render starts by default', () => {
  it('one for a render estimated under SINGLE_WORKER_SECONDS on one worker, whatever the cores', () => {
    expect(estimate(largestSmall)).toBeLessThan(SINGLE_WORKER_SECONDS);
    for (const cores of [1, 2, 8]) {
      expect(workersWorthStarting(scene, 16, 16, cores)).toBe(1);
      expect(workersWorthStarting(scene, largestSmall, largestSmall, cores)).toBe(1);
    }
  });

  it('one per core for a longer render', () => {
    const side = largestSmall + 1;
    expect(estimate(side)).toBeGreaterThanOrEqual(SINGLE_WORKER_SECONDS);
    for (const cores of [1, 2, 8]) expect(workersWorthStarting(scene, side, side, cores)).toBe(cores);
    expect(workersWorthStarting(scene, 4096, 4096, 8)).toBe(8);
  });
});
