import { describe, expect, it } from 'vitest';
import { toastPlace } from '../../../src/ui/lab/toast-place.ts';

describe('toastPlace', () => {
  it('puts a message at the top when the current task is in the lower half of the screen', () => {
    // Level 9 at 1366×768: the current task scrolled in at the column's foot, its Hint button at 745 px.
    expect(toastPlace({ top: 430, height: 340 }, 768)).toBe('top');
    // 200 % zoom: the task card's middle below the middle of a 384 px high screen.
    expect(toastPlace({ top: 282, height: 110 }, 384)).toBe('top');
  });

  it('keeps it at the bottom when the current task is at the top, and when there is none', () => {
    // Level 10: a long task card at the column's top.
    expect(toastPlace({ top: 45, height: 348 }, 768)).toBe('bottom');
    expect(toastPlace(null, 768)).toBe('bottom');
  });
});
