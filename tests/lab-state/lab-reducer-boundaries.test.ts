/**
 * The reducer's boundaries, each checked on both sides: the last value a rule lets in and
 * the first it keeps out. A rule written with `>` where its comment means `>=` (or the
 * reverse) passes a test that only looks far from the edge.
 */
import { describe, expect, it } from 'vitest';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { issueLine } from '../../src/util/issue.ts';
import { BVH_MAX_DEPTH, initialState, type LabState } from '../../src/lab-state/lab-state.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';

/** The default scene (an 8×6 screen) with pixel (x, y) chosen. */
function withPixel(x: number, y: number): LabState {
  const { state, error } = reduce(initialState(defaultScene()), { type: 'pixel.selected', pixel: [x, y] });
  expect(error).toBeUndefined();
  return state;
}

const screenOf = (state: LabState, columns: number, rows: number) => reduce(state, { type: 'camera.changed', changes: { pixels: [columns, rows] } }).state;

describe('pixel.selected: "must be inside the columns×rows screen"', () => {
  const state = initialState(defaultScene());
  const [columns, rows] = state.scene.camera.pixels;

  it('takes the corners (0, 0) and (columns − 1, rows − 1)', () => {
    expect(reduce(state, { type: 'pixel.selected', pixel: [0, 0] }).state.selectedPixel).toEqual([0, 0]);
    expect(reduce(state, { type: 'pixel.selected', pixel: [columns - 1, rows - 1] }).state.selectedPixel).toEqual([columns - 1, rows - 1]);
  });

  it('refuses column `columns`, row `rows`, −1 and a fraction, and keeps the state', () => {
    for (const pixel of [
      [columns, 0],
      [0, rows],
      [-1, 0],
      [0, -1],
      [0.5, 0],
    ] as [number, number][]) {
      const reduction = reduce(state, { type: 'pixel.selected', pixel });
      expect(reduction.error?.map(issueLine)).toEqual([`pixel: must be inside the ${columns}×${rows} screen, got ${pixel[0]},${pixel[1]}`]);
      expect(reduction.state).toBe(state);
    }
  });
});

describe('a smaller screen "may leave the selected pixel outside it"', () => {
  it('a screen of exactly x columns drops pixel x; one of x + 1 keeps it', () => {
    const chosen = withPixel(5, 2);
    expect(screenOf(chosen, 5, 6).selectedPixel).toBeNull();
    expect(screenOf(chosen, 6, 6).selectedPixel).toEqual([5, 2]);
  });

  it('a screen of exactly y rows drops pixel row y; one of y + 1 keeps it', () => {
    const chosen = withPixel(1, 3);
    expect(screenOf(chosen, 8, 3).selectedPixel).toBeNull();
    expect(screenOf(chosen, 8, 4).selectedPixel).toEqual([1, 3]);
  });

  it("a declared view's pixel just off the screen is left out, its ray options kept", () => {
    const state = initialState(defaultScene());
    const [columns, rows] = state.scene.camera.pixels;
    const off = reduce(state, { type: 'view.applied', view: { pixel: [columns, rows - 1], rays: { hideNoHit: true } } });
    expect(off.error).toBeUndefined();
    expect(off.state.selectedPixel).toBeNull();
    expect(off.state.rays.hideNoHit).toBe(true);
    const on = reduce(state, { type: 'view.applied', view: { pixel: [columns - 1, rows - 1] } });
    expect(on.state.selectedPixel).toEqual([columns - 1, rows - 1]);
  });
});

describe('bvh.changed: "a whole number from 0 to BVH_MAX_DEPTH"', () => {
  const state = initialState(defaultScene());

  it('takes 0 and BVH_MAX_DEPTH', () => {
    expect(reduce(state, { type: 'bvh.changed', changes: { depth: 0 } }).state.bvh.depth).toBe(0);
    expect(reduce(state, { type: 'bvh.changed', changes: { depth: BVH_MAX_DEPTH } }).state.bvh.depth).toBe(BVH_MAX_DEPTH);
  });

  it('refuses −1, BVH_MAX_DEPTH + 1 and a fraction, and keeps the state', () => {
    for (const depth of [-1, BVH_MAX_DEPTH + 1, 1.5]) {
      const reduction = reduce(state, { type: 'bvh.changed', changes: { depth } });
      expect(reduction.error?.map(issueLine)).toEqual([`bvh.depth: must be a whole number from 0 to ${BVH_MAX_DEPTH}, got ${depth}`]);
      expect(reduction.state).toBe(state);
    }
  });
});
