import { describe, expect, it } from 'vitest';
import { BURST_GAP_MS, BURST_SCALE, BurstResolution, type BurstTimer } from '../../src/view/burst-resolution.ts';

/** A clock the test moves by hand, with the timers it owes. */
function manualTimer(): BurstTimer & { advance(ms: number): void } {
  let now = 0;
  let next = 1;
  const due = new Map<number, { at: number; callback: () => void }>();
  return {
    now: () => now,
    set: (callback, ms) => {
      due.set(next, { at: now + ms, callback });
      return next++;
    },
    clear: (handle) => due.delete(handle as number),
    advance(ms) {
      now += ms;
      for (const [handle, timer] of [...due]) {
        if (timer.at > now) continue;
        due.delete(handle);
        timer.callback();
      }
    },
  };
}

/** A BurstResolution on a manual clock, with the scales it applied. */
function watched() {
  const timer = manualTimer();
  const scales: number[] = [];
  const resolution = new BurstResolution((scale) => scales.push(scale), timer);
  return { timer, scales, resolution };
}

describe('BurstResolution', () => {
  it('keeps a single edit at full resolution', () => {
    const { timer, scales, resolution } = watched();
    resolution.edited();
    timer.advance(BURST_GAP_MS * 2);
    resolution.edited();
    timer.advance(BURST_GAP_MS * 2);
    expect(scales).toEqual([]);
    expect(resolution.reducing).toBe(false);
  });

  it('draws a burst at reduced resolution and sharp again once the edits stop', () => {
    const { timer, scales, resolution } = watched();
    resolution.edited();
    timer.advance(16);
    resolution.edited();
    expect(scales).toEqual([BURST_SCALE]);
    // Steps keep coming: no switching back and forth in between.
    for (let step = 0; step < 20; step++) {
      timer.advance(BURST_GAP_MS - 1);
      resolution.edited();
    }
    expect(scales).toEqual([BURST_SCALE]);
    expect(resolution.reducing).toBe(true);
    timer.advance(BURST_GAP_MS);
    expect(scales).toEqual([BURST_SCALE, 1]);
    expect(resolution.reducing).toBe(false);
  });

  it('leaves nothing pending once disposed', () => {
    const { timer, scales, resolution } = watched();
    resolution.edited();
    resolution.edited();
    resolution.dispose();
    timer.advance(BURST_GAP_MS * 2);
    expect(scales).toEqual([BURST_SCALE]);
  });
});
