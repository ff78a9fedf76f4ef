import { describe, expect, it } from 'vitest';
import { FrameScheduler, type FrameHost } from '../../src/view/frame-scheduler.ts';

/** A frame host driven by the test: frames run only when `tick()` is called. */
function manualFrames() {
  let queue: ((time: number) => void)[] = [];
  let time = 0;
  const host: FrameHost = {
    requestFrame: (callback) => queue.push(callback),
    cancelFrame: () => {
      queue = [];
    },
  };
  return {
    host,
    pending: () => queue.length,
    tick(ms = 16) {
      time += ms;
      const run = queue;
      queue = [];
      for (const callback of run) callback(time);
    },
  };
}

describe('rendering on demand', () => {
  it('draws once per request, however many requests a frame gets, and nothing when idle', () => {
    const frames = manualFrames();
    let draws = 0;
    const scheduler = new FrameScheduler(() => draws++, frames.host);
    scheduler.requestRender();
    scheduler.requestRender();
    scheduler.requestRender();
    expect(frames.pending()).toBe(1);
    frames.tick();
    expect(draws).toBe(1);
    for (let i = 0; i < 10; i++) frames.tick();
    expect(draws).toBe(1);
    expect(frames.pending()).toBe(0);
  });

  it('keeps frames coming while an animator is moving, then stops', () => {
    const frames = manualFrames();
    let draws = 0;
    const scheduler = new FrameScheduler(() => draws++, frames.host);
    let left = 3;
    const seen: number[] = [];
    scheduler.addAnimator((time) => {
      seen.push(time);
      return --left > 0;
    });
    for (let i = 0; i < 10; i++) frames.tick();
    expect(draws).toBe(3);
    expect(seen).toEqual([16, 32, 48]);
    expect(frames.pending()).toBe(0);
  });

  it('asks an idle animator again on the next requested frame (the rays’ animation restarts)', () => {
    const frames = manualFrames();
    const scheduler = new FrameScheduler(() => {}, frames.host);
    let calls = 0;
    scheduler.addAnimator(() => {
      calls++;
      return false;
    });
    frames.tick();
    scheduler.requestRender();
    frames.tick();
    expect(calls).toBe(2);
  });

  it('forgets a removed animator, even one that removes itself mid-frame', () => {
    const frames = manualFrames();
    const scheduler = new FrameScheduler(() => {}, frames.host);
    let calls = 0;
    const remove = scheduler.addAnimator(() => {
      calls++;
      remove();
      return true;
    });
    frames.tick();
    // It said "still moving" as it left: one more frame, then quiet.
    expect(frames.pending()).toBe(1);
    for (let i = 0; i < 5; i++) frames.tick();
    expect(calls).toBe(1);
    expect(frames.pending()).toBe(0);
  });

  it('draws at once on renderNow (a resized canvas) and nothing after dispose', () => {
    const frames = manualFrames();
    let draws = 0;
    const scheduler = new FrameScheduler(() => draws++, frames.host);
    scheduler.requestRender();
    scheduler.renderNow(5);
    expect(draws).toBe(1);
    scheduler.dispose();
    scheduler.requestRender();
    frames.tick();
    expect(draws).toBe(1);
  });
});
