import { expect, test } from 'vitest';
import { FrameThrottle } from '../../../src/ui/controls/frame-throttle.ts';
import { manualFrames } from '../../support/manual-frames.ts';

/** A throttle on frames that run only when the test ticks them, and what it sent. */
function throttled() {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle = new FrameThrottle<number>((value) => sent.push(value), frames.host);
  return { frames, sent, throttle };
}

test('the first value goes out at once, not at the next frame', () => {
  const { sent, throttle } = throttled();
  throttle.push(1);
  expect(sent).toEqual([1]);
});

test('values pushed within a frame after the first wait for it, and only the latest goes out', () => {
  const { frames, sent, throttle } = throttled();
  throttle.push(1);
  throttle.push(2);
  throttle.push(3);
  expect(sent).toEqual([1]);
  frames.tick();
  expect(sent).toEqual([1, 3]);
  // Sent at that frame: the next value waits for the frame after it.
  throttle.push(4);
  expect(sent).toEqual([1, 3]);
  frames.tick();
  expect(sent).toEqual([1, 3, 4]);
});

test('one value a frame, as a drag delivers them, goes out at once every time', () => {
  const { frames, sent, throttle } = throttled();
  for (let value = 1; value <= 5; value++) {
    throttle.push(value);
    expect(sent.at(-1)).toBe(value);
    frames.tick();
  }
  expect(sent).toEqual([1, 2, 3, 4, 5]);
  frames.tick();
  expect(frames.pending()).toBe(0);
});

test('a frame with nothing waiting sends nothing and asks for no more frames', () => {
  const { frames, sent, throttle } = throttled();
  throttle.push(1);
  frames.tick();
  expect(frames.pending()).toBe(0);
  expect(sent).toEqual([1]);
});

test('cancel drops the waiting value', () => {
  const { frames, sent, throttle } = throttled();
  throttle.push(1);
  throttle.push(2);
  throttle.cancel();
  frames.tick();
  expect(sent).toEqual([1]);
  throttle.push(3);
  expect(sent).toEqual([1, 3]);
});

test('a value pushed while one is being sent waits for the frame', () => {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle: FrameThrottle<number> = new FrameThrottle<number>((value) => {
    sent.push(value);
    if (value === 1) throttle.push(10);
  }, frames.host);
  throttle.push(1);
  expect(sent).toEqual([1]);
  frames.tick();
  expect(sent).toEqual([1, 10]);
});
