/** Advances something animated to `timeMs`; returns true while it needs more frames. */
export type Animator = (timeMs: number) => boolean;

/** The browser's frame hook, injectable so the scheduler (and the controls' FrameThrottle) runs and is tested without a page. */
export interface FrameHost {
  requestFrame(callback: (timeMs: number) => void): number;
  cancelFrame(handle: number): void;
}

export const browserFrames: FrameHost = {
  requestFrame: (callback) => requestAnimationFrame(callback),
  cancelFrame: (handle) => cancelAnimationFrame(handle),
};

/**
 * Renders on demand: a change asks for one frame, and frames keep coming only while an
 * animator says it is still moving. An idle view costs no CPU at all (a school laptop's
 * fan stays quiet), unlike a render loop that draws the same picture 60 times a second.
 */
export class FrameScheduler {
  private readonly animators = new Set<Animator>();
  private pending: number | null = null;
  private disposed = false;
  /** The timer that ends a hold (holdFor), or null when frames are not held. */
  private hold: ReturnType<typeof setTimeout> | null = null;
  /** Whether a frame was asked for during the hold. */
  private heldFrame = false;
  /** Set by release(): the next frame shows what a hold waited for, so no new hold delays it. */
  private releasedFrame = false;
  /** Whether the next frame was asked for by a change (requestRender), not only to go on drawing (requestMore). */
  private changed = false;

  /**
   * `draw` renders one frame; it runs after the animators of that frame. `changed` is false
   * for a frame asked for only by `requestMore` (with no animator moving): the picture has
   * not changed since the last frame, which may go on drawing it (view/piecewise-rays.ts).
   */
  constructor(
    private readonly draw: (changed: boolean) => void,
    private readonly host: FrameHost = browserFrames,
  ) {}

  /**
   * Whether no frame is coming: none scheduled, none waiting for a hold to end. A scheduled
   * frame can wait seconds for the browser's next frame (on SwiftShader while the GPU process
   * compiles the shaders of the last one), so a second without frames does not prove this.
   */
  get idle(): boolean {
    return this.pending === null && !this.heldFrame;
  }

  /** Schedules one frame, unless one is already scheduled (or frames are held: then at the hold's end). */
  requestRender(): void {
    if (this.disposed) return;
    this.changed = true;
    if (this.hold !== null) {
      this.heldFrame = true;
      return;
    }
    if (this.pending !== null) return;
    this.pending = this.host.requestFrame((timeMs) => this.frame(timeMs));
  }

  /**
   * Schedules one more frame of the same picture, to go on drawing it (a held frame waits
   * for the hold's end like any other): `draw` is told that nothing changed unless a change
   * asks for that frame too.
   */
  requestMore(): void {
    if (this.disposed || this.pending !== null) return;
    if (this.hold !== null) {
      this.heldFrame = true;
      return;
    }
    this.pending = this.host.requestFrame((timeMs) => this.frame(timeMs));
  }

  /**
   * Draws no frame for up to `ms`, or until `release()`: a frame asked for meanwhile (or
   * already scheduled) is drawn then. The lab holds its frames after an edit until the
   * edit's rays arrive, so that one frame shows both (see LabView). A hold running already
   * is not made longer, so a stream of edits still gets a frame at least every `ms`; nor
   * does a hold start between a release and the frame it lets through: an edit that came
   * before the previous edit's rays were drawn would otherwise hold them back again, and
   * edits faster than the rays' round trip would starve the view of rays.
   * `renderNow` still draws.
   */
  holdFor(ms: number): void {
    if (this.disposed || this.hold !== null || this.releasedFrame) return;
    if (this.pending !== null) {
      this.host.cancelFrame(this.pending);
      this.pending = null;
      this.heldFrame = true;
    }
    this.hold = setTimeout(() => this.release(), ms);
  }

  /**
   * What frames were held for has come (or the hold ran out): the frame asked for during the
   * hold, if any, is scheduled, and no hold delays the frame scheduled now (ask for the
   * frame first, then release).
   */
  release(): void {
    if (this.hold !== null) {
      clearTimeout(this.hold);
      this.hold = null;
      if (this.heldFrame) {
        this.heldFrame = false;
        this.requestRender();
      }
    }
    this.releasedFrame = this.pending !== null;
  }

  /**
   * Calls `animator` on every frame from now on, and keeps frames coming while it returns
   * true. Returns the function that removes it.
   */
  addAnimator(animator: Animator): () => void {
    this.animators.add(animator);
    this.requestRender();
    return () => {
      this.animators.delete(animator);
    };
  }

  /** Renders now (after a resize, whose new canvas size is blank until drawn). */
  renderNow(timeMs = performance.now()): void {
    if (this.pending !== null) this.host.cancelFrame(this.pending);
    this.changed = true;
    this.frame(timeMs);
  }

  dispose(): void {
    if (this.pending !== null) this.host.cancelFrame(this.pending);
    if (this.hold !== null) clearTimeout(this.hold);
    this.pending = null;
    this.hold = null;
    this.animators.clear();
    this.disposed = true;
  }

  private frame(timeMs: number): void {
    this.pending = null;
    this.releasedFrame = false;
    let moving = false;
    // A copy: an animator may remove itself (a finished flight) while we iterate.
    for (const animator of [...this.animators]) {
      if (animator(timeMs)) moving = true;
    }
    const changed = this.changed || moving;
    this.changed = false;
    this.draw(changed);
    if (moving) this.requestRender();
  }
}
