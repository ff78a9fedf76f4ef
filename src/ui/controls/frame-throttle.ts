import { browserFrames, type FrameHost } from '../../view/frame-scheduler.ts';

/**
 * Passes on the values of a dragged control (a slider's or colour picker's `input` events):
 * the first at once, then at most one per animation frame, the latest. The display
 * refreshes once a frame anyway, so more would only flood the store and the ray tracer with
 * changes nobody sees.
 *
 * The first value is not held for the next frame: Chromium already delivers a drag's mouse
 * moves once a frame, just before the frame's callbacks, and a value held for a callback of
 * that frame reached the store after the 3D view had drawn the frame with the old rays. On
 * a CPU rasterizer that stale frame cost 50–100 ms of drawing before the new rays could be
 * drawn (docs/benchmark-log.md, ninth round). Sent at once, the edit starts its trace and the
 * view's wait for its rays (LabView) before the frame is drawn.
 */
export class FrameThrottle<T> {
  private pending: { value: T } | null = null;
  /** The frame that ends the current window (0: no value sent since the last frame). */
  private frame = 0;

  constructor(
    private readonly send: (value: T) => void,
    private readonly frames: FrameHost = browserFrames,
  ) {}

  /** Sends `value` now if none was sent since the last frame; else at the next frame, replacing any value still waiting. */
  push(value: T): void {
    if (this.frame) {
      this.pending = { value };
      return;
    }
    // The window opens before the value goes out, so a push made while it is being sent waits.
    this.frame = this.frames.requestFrame(() => this.flush());
    this.send(value);
  }

  /** Drops a waiting value (a commit replaces it, or the element left the page). */
  cancel(): void {
    if (this.frame) this.frames.cancelFrame(this.frame);
    this.frame = 0;
    this.pending = null;
  }

  private flush(): void {
    const pending = this.pending;
    this.frame = 0;
    this.pending = null;
    if (pending) this.push(pending.value);
  }
}
