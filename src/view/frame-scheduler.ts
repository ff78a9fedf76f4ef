/** Advances something animated to `timeMs`; returns true while it needs more frames. */
export type Animator = (timeMs: number) => boolean;

/** The browser's frame hook, injectable so the scheduler runs (and is tested) without a page. */
export interface FrameHost {
  requestFrame(callback: (timeMs: number) => void): number;
  cancelFrame(handle: number): void;
}

const browserFrames: FrameHost = {
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

  /** `draw` renders one frame; it runs after the animators of that frame. */
  constructor(
    private readonly draw: () => void,
    private readonly host: FrameHost = browserFrames,
  ) {}

  /** Schedules one frame, unless one is already scheduled. */
  requestRender(): void {
    if (this.pending !== null || this.disposed) return;
    this.pending = this.host.requestFrame((timeMs) => this.frame(timeMs));
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
    this.frame(timeMs);
  }

  dispose(): void {
    if (this.pending !== null) this.host.cancelFrame(this.pending);
    this.pending = null;
    this.animators.clear();
    this.disposed = true;
  }

  private frame(timeMs: number): void {
    this.pending = null;
    let moving = false;
    // A copy: an animator may remove itself (a finished flight) while we iterate.
    for (const animator of [...this.animators]) {
      if (animator(timeMs)) moving = true;
    }
    this.draw();
    if (moving) this.requestRender();
  }
}
