import { describe, expect, it } from 'vitest';
import { axisEnd, fiveNumbers, quantile } from '../../src/classroom/dashboard-stats.ts';

describe('dashboard statistics', () => {
  it('gives the median of an odd and an even number of values', () => {
    expect(fiveNumbers([5, 1, 3])?.median).toBe(3);
    expect(fiveNumbers([4, 1, 3, 2])?.median).toBe(2.5);
  });

  it('interpolates quartiles like R, NumPy and QUARTILE.INC (type 7)', () => {
    // numpy.percentile([1,2,3,4,5,6,7,8,9,10], [25, 75]) → [3.25, 7.75]
    expect(fiveNumbers([10, 9, 8, 7, 6, 5, 4, 3, 2, 1])).toEqual({ count: 10, min: 1, q1: 3.25, median: 5.5, q3: 7.75, max: 10 });
    expect(quantile([2, 4], 0.25)).toBe(2.5);
  });

  it('handles one value and none', () => {
    expect(fiveNumbers([7])).toEqual({ count: 1, min: 7, q1: 7, median: 7, q3: 7, max: 7 });
    expect(fiveNumbers([])).toBeNull();
    expect(quantile([], 0.5)).toBeNaN();
  });

  it('ends a time axis at the longest time that is not an outlier', () => {
    const row = (times: number[]) => ({ times, stats: fiveNumbers(times) });
    // Q1 22.5, Q3 55: the fence is 55 + 1.5 × 32.5 = 103.75; 1200 is beyond it, 60 the last one inside.
    const tasks = [row([10, 20, 30, 40, 60, 1200]), row([5, 8])];
    expect(tasks[0].stats).toMatchObject({ q1: 22.5, q3: 55 });
    expect(axisEnd(tasks)).toBe(60);
    expect(axisEnd([row([])])).toBe(0);
    expect(axisEnd([row([100, 100, 100])])).toBe(100);
  });
});
