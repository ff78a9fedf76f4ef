import { describe, expect, it } from 'vitest';
import { effectiveFocusDistance, focusDistanceTo } from '../../src/scene/camera-focus.ts';

describe('camera focus', () => {
  const camera = { position: [0, 1, 5] as [number, number, number], target: [0, 1, 0] as [number, number, number] };

  it('puts a point on the plane in focus: its distance along the view direction, not straight-line', () => {
    expect(focusDistanceTo(camera, [0, 1, 2])).toBeCloseTo(3, 12);
    // Off to the side, the plane perpendicular to the view still passes through it.
    expect(focusDistanceTo(camera, [2, 0, 1])).toBeCloseTo(4, 12);
  });

  it('keeps within the schema: a point behind the camera gets the nearest plane', () => {
    expect(focusDistanceTo(camera, [0, 1, 9])).toBe(0.05);
    expect(focusDistanceTo(camera, [0, 1, -500])).toBe(100);
  });

  it('left out, the focus distance is the distance to the target', () => {
    expect(effectiveFocusDistance({ ...camera, target: [3, 5, 5] })).toBeCloseTo(5, 12);
    expect(effectiveFocusDistance({ ...camera, focusDistance: 2 })).toBe(2);
  });
});
