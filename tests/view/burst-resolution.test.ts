import { describe, expect, it } from 'vitest';
import { BURST_GAP_MS, BURST_SCALE, BurstResolution, HEAVY_BURST_SCALE } from '../../src/view/burst-resolution.ts';
import { manualTimer } from '../support/manual-timer.ts';

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

  it('draws coarse from the first edit while held, between edits too, and sharp at once when let go', () => {
    const { timer, scales, resolution } = watched();
    resolution.edited();
    resolution.hold(BURST_SCALE);
    expect(scales).toEqual([BURST_SCALE]);
    expect(resolution.holding).toBe(true);
    for (let step = 0; step < 5; step++) {
      timer.advance(BURST_GAP_MS * 3);
      resolution.edited();
    }
    expect(scales).toEqual([BURST_SCALE]);
    resolution.hold(null);
    expect(scales).toEqual([BURST_SCALE, 1]);
    timer.advance(BURST_GAP_MS * 3);
    expect(scales).toEqual([BURST_SCALE, 1]);
    expect(resolution.reducing).toBe(false);
  });

  it('holds a burst already coarse without drawing it again', () => {
    const { timer, scales, resolution } = watched();
    resolution.edited();
    timer.advance(16);
    resolution.edited();
    resolution.hold(BURST_SCALE);
    timer.advance(BURST_GAP_MS * 2);
    expect(scales).toEqual([BURST_SCALE]);
    resolution.hold(null);
    expect(scales).toEqual([BURST_SCALE, 1]);
  });

  it('holds a heavy screen coarser, from a burst already coarse too, and sharp at once when let go', () => {
    const { timer, scales, resolution } = watched();
    resolution.edited();
    timer.advance(16);
    resolution.edited();
    resolution.hold(HEAVY_BURST_SCALE);
    expect(HEAVY_BURST_SCALE).toBeLessThan(BURST_SCALE);
    expect(scales).toEqual([BURST_SCALE, HEAVY_BURST_SCALE]);
    // Edits while held, far apart or close together, leave the scale the hold asked.
    for (const gap of [16, BURST_GAP_MS * 3, 16]) {
      timer.advance(gap);
      resolution.edited();
      resolution.hold(HEAVY_BURST_SCALE);
    }
    expect(scales).toEqual([BURST_SCALE, HEAVY_BURST_SCALE]);
    resolution.hold(null);
    expect(scales).toEqual([BURST_SCALE, HEAVY_BURST_SCALE, 1]);
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
