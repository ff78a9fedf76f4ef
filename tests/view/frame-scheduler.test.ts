import { afterEach, describe, expect, it, vi } from 'vitest';
import { FrameScheduler } from '../../src/view/frame-scheduler.ts';
import { manualFrames } from '../support/manual-frames.ts';

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

  it('tells a frame asked for only to go on drawing (requestMore) from one a change asked for', () => {
    const frames = manualFrames();
    const seen: boolean[] = [];
    const scheduler = new FrameScheduler((changed) => seen.push(changed), frames.host);
    scheduler.requestRender();
    frames.tick();
    scheduler.requestMore();
    scheduler.requestMore();
    frames.tick();
    // A change during the pieces makes the next frame a changed one, asked for once.
    scheduler.requestMore();
    scheduler.requestRender();
    expect(frames.pending()).toBe(1);
    frames.tick();
    frames.tick();
    expect(seen).toEqual([true, false, true]);
    // A moving animator changes its frame (and asks for the next as a change); a still one does not.
    let moves = 1;
    scheduler.addAnimator(() => moves-- > 0);
    frames.tick();
    frames.tick();
    scheduler.requestMore();
    frames.tick();
    expect(seen).toEqual([true, false, true, true, true, false]);
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

/** A scheduler on manual frames and fake timers (for holds); `draws()` counts its frames. */
function withFakeTimers() {
  vi.useFakeTimers();
  const frames = manualFrames();
  let count = 0;
  const scheduler = new FrameScheduler(() => count++, frames.host);
  return { frames, scheduler, draws: () => count };
}

describe('holding frames back (an edit waits for its rays)', () => {
  afterEach(() => vi.useRealTimers());

  it('is idle only while no frame is coming: none scheduled, none waiting for a hold', () => {
    const { frames, scheduler } = withFakeTimers();
    expect(scheduler.idle).toBe(true);
    scheduler.requestRender();
    expect(scheduler.idle).toBe(false);
    frames.tick();
    expect(scheduler.idle).toBe(true);
    // A hold alone brings no frame; a frame asked for during it comes at its end.
    scheduler.holdFor(60);
    expect(scheduler.idle).toBe(true);
    scheduler.requestMore();
    expect(scheduler.idle).toBe(false);
    vi.advanceTimersByTime(60);
    expect(scheduler.idle).toBe(false);
    frames.tick();
    expect(scheduler.idle).toBe(true);
    // A moving animator keeps the next frame coming.
    let moves = 2;
    scheduler.addAnimator(() => moves-- > 0);
    frames.tick();
    expect(scheduler.idle).toBe(false);
    frames.tick();
    frames.tick();
    expect(scheduler.idle).toBe(true);
  });

  it('draws a frame asked for during a hold once it is released, and only one', () => {
    const { frames, scheduler, draws } = withFakeTimers();
    scheduler.requestRender(); // scheduled before the hold: held too
    scheduler.holdFor(60);
    scheduler.requestRender();
    frames.tick();
    expect(draws()).toBe(0);
    scheduler.release();
    scheduler.release();
    frames.tick();
    frames.tick();
    expect(draws()).toBe(1);
  });

  it('ends a hold by itself after its time, and draws nothing then if nothing was asked for', () => {
    const { frames, scheduler, draws } = withFakeTimers();
    scheduler.holdFor(60);
    vi.advanceTimersByTime(60);
    frames.tick();
    expect(draws()).toBe(0);
    scheduler.holdFor(60);
    scheduler.requestRender();
    vi.advanceTimersByTime(59);
    frames.tick();
    expect(draws()).toBe(0);
    vi.advanceTimersByTime(1);
    frames.tick();
    expect(draws()).toBe(1);
  });

  it('is not made longer by a second hold, so a stream of edits still gets frames', () => {
    const { frames, scheduler, draws } = withFakeTimers();
    for (let edit = 0; edit < 6; edit++) {
      scheduler.holdFor(60);
      scheduler.requestRender();
      vi.advanceTimersByTime(20);
      frames.tick(20);
    }
    // 120 ms of edits every 20 ms: the holds ended at 60 and 120 ms.
    expect(draws()).toBe(2);
  });

  it('does not hold again, for the next edit, a frame released for the rays it waited for', () => {
    const { frames, scheduler, draws } = withFakeTimers();
    scheduler.holdFor(60);
    scheduler.requestRender();
    scheduler.release(); // the edit's rays
    scheduler.holdFor(60); // the next edit, before the frame that draws them
    scheduler.requestRender();
    frames.tick();
    expect(draws()).toBe(1);
    // Once that frame is drawn, an edit holds frames again.
    scheduler.holdFor(60);
    scheduler.requestRender();
    frames.tick();
    expect(draws()).toBe(1);
  });

  it('does not hold a frame for rays that came with no hold running', () => {
    const { frames, scheduler, draws } = withFakeTimers();
    scheduler.requestRender(); // rays arrive after a hold ran out
    scheduler.release();
    scheduler.holdFor(60);
    frames.tick();
    expect(draws()).toBe(1);
  });

  it('still draws at once on renderNow, and holds nothing after dispose', () => {
    const { frames, scheduler, draws } = withFakeTimers();
    scheduler.holdFor(60);
    scheduler.renderNow(5);
    expect(draws()).toBe(1);
    scheduler.dispose();
    scheduler.holdFor(60);
    vi.advanceTimersByTime(100);
    frames.tick();
    expect(draws()).toBe(1);
  });
});
