import { expect, test } from 'vitest';
import { FrameThrottle, type ThrottleFrames } from '../../../src/ui/controls/frame-throttle.ts';

/** Frames that run only when the test says so. */
function manualFrames(): ThrottleFrames & { runFrame(): void; waiting: number } {
  let callbacks = new Map<number, () => void>();
  let next = 1;
  return {
    request(callback) {
      callbacks.set(next, callback);
      return next++;
    },
    cancel(handle) {
      callbacks.delete(handle);
    },
    runFrame() {
      const due = callbacks;
      callbacks = new Map();
      for (const callback of due.values()) callback();
    },
    get waiting() {
      return callbacks.size;
    },
  };
}

test('the first value goes out at once, not at the next frame', () => {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle = new FrameThrottle<number>((value) => sent.push(value), frames);
  throttle.push(1);
  expect(sent).toEqual([1]);
});

test('values pushed within a frame after the first wait for it, and only the latest goes out', () => {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle = new FrameThrottle<number>((value) => sent.push(value), frames);
  throttle.push(1);
  throttle.push(2);
  throttle.push(3);
  expect(sent).toEqual([1]);
  frames.runFrame();
  expect(sent).toEqual([1, 3]);
  // Sent at that frame: the next value waits for the frame after it.
  throttle.push(4);
  expect(sent).toEqual([1, 3]);
  frames.runFrame();
  expect(sent).toEqual([1, 3, 4]);
});

test('one value a frame, as a drag delivers them, goes out at once every time', () => {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle = new FrameThrottle<number>((value) => sent.push(value), frames);
  for (let value = 1; value <= 5; value++) {
    throttle.push(value);
    expect(sent.at(-1)).toBe(value);
    frames.runFrame();
  }
  expect(sent).toEqual([1, 2, 3, 4, 5]);
  frames.runFrame();
  expect(frames.waiting).toBe(0);
});

test('a frame with nothing waiting sends nothing and asks for no more frames', () => {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle = new FrameThrottle<number>((value) => sent.push(value), frames);
  throttle.push(1);
  frames.runFrame();
  expect(frames.waiting).toBe(0);
  expect(sent).toEqual([1]);
});

test('cancel drops the waiting value', () => {
  const frames = manualFrames();
  const sent: number[] = [];
  const throttle = new FrameThrottle<number>((value) => sent.push(value), frames);
  throttle.push(1);
  throttle.push(2);
  throttle.cancel();
  frames.runFrame();
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
  }, frames);
  throttle.push(1);
  expect(sent).toEqual([1]);
  frames.runFrame();
  expect(sent).toEqual([1, 10]);
});
