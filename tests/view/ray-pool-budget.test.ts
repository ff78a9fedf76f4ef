import { describe, expect, it } from 'vitest';
import { DEFAULT_RAY_VIEW, type RayViewOptions } from '../../src/lab-state/lab-state.ts';
import { flattenRays } from '../../src/view/flat-rays.ts';
import { keptRays } from '../../src/view/ray-budget.ts';
import { RayPool } from '../../src/view/ray-pool.ts';
import { syntheticScreen } from '../support/ray-fixtures.ts';

// The ray pool under the live view's budget while the learner edits (src/view/ray-budget.ts).

const options = (changes: Partial<RayViewOptions> = {}): RayViewOptions => ({ ...DEFAULT_RAY_VIEW, ...changes });

describe('RayPool budget', () => {
  it('draws at most about the budget while one is set, says how many of how many, and all again without', () => {
    const pool = new RayPool();
    const rays = syntheticScreen(6000);
    pool.update(rays, options(), null);
    const all = pool.stats.rays;
    expect(pool.thinning).toBeNull();
    pool.setBudget(1000);
    expect(pool.stats.rays).toBeGreaterThan(900);
    expect(pool.stats.rays).toBeLessThanOrEqual(1005);
    expect(pool.thinning).toEqual({ shown: pool.stats.rays, of: all, oneSample: false });
    // A screen traced from one sample per pixel is told with the count of the screen before it.
    const sampled = syntheticScreen(300);
    pool.update({ ...sampled, traces: sampled.traces.map((trace) => ({ ...trace, onlySample: 0 })) }, options(), null);
    expect(pool.thinning).toEqual({ shown: 300, of: all, oneSample: true });
    // A screen that fits is drawn whole under the budget too.
    pool.update(syntheticScreen(500), options(), null);
    expect(pool.thinning).toBeNull();
    pool.update(rays, options(), null);
    pool.setBudget(null);
    expect(pool.stats.rays).toBe(all);
    expect(pool.thinning).toBeNull();
  });
});

describe('RayPool budget chosen ahead', () => {
  it('chooses the budget’s rays of the screen drawn now once, ahead of the edit, and the edit draws that choice', () => {
    const pool = new RayPool();
    const rays = syntheticScreen(6000);
    pool.update(rays, options(), null);
    pool.prepareBudget(1000);
    const ahead = keptRays(flattenRays(rays), 1000, null);
    expect(keptRays(flattenRays(rays), 1000, null)).toBe(ahead);
    pool.setBudget(1000);
    expect(pool.stats.rays).toBe(ahead!.reduce((sum, kept) => sum + kept, 0));
    // Another budget is chosen again, not taken from the last choice.
    expect(keptRays(flattenRays(rays), 500, null)).not.toBe(ahead);
  });
});
