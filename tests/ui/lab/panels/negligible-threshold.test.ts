// "Negligible below" must be easy to set to a round share by dragging (issue 37: 10 % took
// four drags, as level 12 asks for exactly 10 %).
import { expect, test } from 'vitest';
import { DEFAULT_RAY_VIEW } from '../../../../src/lab-state/lab-state.ts';
import { NEGLIGIBLE_THRESHOLD } from '../../../../src/ui/lab/panels/negligible-threshold.ts';

const { min, max, step } = NEGLIGIBLE_THRESHOLD;

/** Whether `value` is one of the slider's stops, min + k·step. */
const isStop = (value: number) => Math.abs(Math.round((value - min) / step) * step + min - value) < 1e-12;

test('10 %, the lab’s default and the ends are stops of the slider', () => {
  for (const share of [0.1, DEFAULT_RAY_VIEW.negligibleThreshold, min, max]) expect(isStop(share), String(share)).toBe(true);
});

test('each stop is several pixels wide on a 200 px slider, so a drag can land on one', () => {
  // The sidebar's track is 251 px wide at 1366 × 768 (measured in Chromium); 200 px leaves room for narrower screens.
  expect((200 * step) / (max - min)).toBeGreaterThanOrEqual(4);
});
