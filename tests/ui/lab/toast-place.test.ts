import { describe, expect, it } from 'vitest';
import { clearToastPlace, toastPlace } from '../../../src/ui/lab/toast-place.ts';

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

describe('clearToastPlace', () => {
  // The task column at 1366×768 (lab-layout.css.ts): a message of 115 px at its top under the header, or at its foot.
  const boxAt = (place: 'top' | 'bottom') => (place === 'top' ? { top: 52, height: 115 } : { top: 637, height: 115 });

  it("leaves the top when a message there would cover the level's intro", () => {
    // Level 21 opening: title and intro 53–362 px, the first task 372–575 px, below the middle.
    const intro = { top: 53, height: 309 };
    const task = { top: 372, height: 203 };
    expect(toastPlace(task, 768)).toBe('top');
    expect(clearToastPlace([intro, task], 'top', boxAt, true)).toBe('bottom');
  });

  it('goes over the panels when each end covers the intro or the task', () => {
    const intro = { top: 53, height: 309 };
    const tallTask = { top: 372, height: 380 };
    expect(clearToastPlace([intro, tallTask], 'top', boxAt, true)).toBe('panels');
    // Without the panels beside the view (a phone), it keeps the end away from the task.
    expect(clearToastPlace([intro, tallTask], 'top', boxAt, false)).toBe('top');
  });

  it('keeps the preferred end when it covers nothing kept, and ignores what is not drawn', () => {
    const scrolledTask = { top: 45, height: 348 };
    expect(clearToastPlace([{ top: -400, height: 300 }, scrolledTask], 'bottom', boxAt, true)).toBe('bottom');
    expect(clearToastPlace([{ top: 0, height: 0 }], 'top', boxAt, true)).toBe('top');
    expect(clearToastPlace([], 'bottom', boxAt, true)).toBe('bottom');
  });
});
