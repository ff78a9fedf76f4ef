import { describe, expect, it } from 'vitest';
import { estimateRender } from '../../src/render/render-estimate.ts';
import { ESTIMATED_SECONDS_PER_WORKER, workersWorthStarting } from '../../src/cli/workers-worth-starting.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';

const scene = defaultScene();
/** The side of a square image whose one-worker estimate is about `seconds`. */
function sideFor(seconds: number): number {
  return Math.round(Math.sqrt(seconds / estimateRender(scene, 1, 1, 1).seconds));
}

describe('the workers rt render starts by default', () => {
  it('one for a small render, whatever the cores', () => {
    for (const cores of [1, 2, 8]) expect(workersWorthStarting(scene, 16, 16, cores)).toBe(1);
    const justUnder = sideFor(2 * ESTIMATED_SECONDS_PER_WORKER) - 2;
    expect(estimateRender(scene, justUnder, justUnder, 1).seconds).toBeLessThan(2 * ESTIMATED_SECONDS_PER_WORKER);
    expect(workersWorthStarting(scene, justUnder, justUnder, 8)).toBe(1);
  });

  it('one more for each ESTIMATED_SECONDS_PER_WORKER of the one-worker estimate, up to one per core', () => {
    const side = sideFor(3.2 * ESTIMATED_SECONDS_PER_WORKER);
    expect(workersWorthStarting(scene, side, side, 8)).toBe(3);
    expect(workersWorthStarting(scene, side, side, 2)).toBe(2);
    expect(workersWorthStarting(scene, side, side, 1)).toBe(1);
    expect(workersWorthStarting(scene, 4096, 4096, 8)).toBe(8);
  });
});
