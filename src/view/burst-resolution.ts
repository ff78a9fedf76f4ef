/** The timer a burst waits on, injectable so that the logic is tested without a page. */
export interface BurstTimer {
  now(): number;
  set(callback: () => void, ms: number): unknown;
  clear(handle: unknown): void;
}

export const browserTimer: BurstTimer = {
  now: () => performance.now(),
  set: (callback, ms) => setTimeout(callback, ms),
  clear: (handle) => clearTimeout(handle as ReturnType<typeof setTimeout>),
};

/** Edits closer together than this are one burst (a slider dragged or a key held). */
export const BURST_GAP_MS = 300;
/** The share of the pixel ratio a burst draws at: a quarter of the pixels. */
export const BURST_SCALE = 0.5;

/**
 * The 3D view's drawing resolution during a burst of edits, on a CPU rasterizer
 * (SwiftShader, llvmpipe). There a frame of the lab costs 80–105 ms at full size, about half
 * of it per pixel, so a dragged slider's rays reached the screen 0.35–0.5 s after each step.
 * Drawn at half the pixel ratio during the drag, over five paired runs the median step went
 * from 369 to 284 ms and the 95th percentile from 517 to 375 ms (docs/benchmark-log.md). A
 * single edit stays sharp: only the second edit within BURST_GAP_MS starts the reduced
 * drawing, and BURST_GAP_MS after the last edit the view is drawn at full resolution again.
 * This is the adaptive degradation interactive viewers use (draw coarse while the user moves
 * things, sharp once they stop).
 *
 * While the rays are held to a budget (`hold`, view/ray-budget.ts) the view draws coarse from
 * the first edit and stays so between edits: there a sharp frame of 1,000 rays cost 120–250
 * ms on SwiftShader, and each switch between sharp and coarse waits for the frame before it, so steps a
 * few tenths of a second apart waited 0.2–1.2 s each. Let go, it is drawn sharp at once,
 * with every ray (one frame).
 */
export class BurstResolution {
  private lastEdit = -Infinity;
  private reduced = false;
  private restore: unknown = null;
  private held = false;

  /** `apply(scale)` redraws the view at `scale` × its pixel ratio (1: full resolution). */
  constructor(
    private readonly apply: (scale: number) => void,
    private readonly timer: BurstTimer = browserTimer,
  ) {}

  /** Whether the view draws at reduced resolution now. */
  get reducing(): boolean {
    return this.reduced;
  }

  /** The scene was edited now. */
  edited(): void {
    const now = this.timer.now();
    const inBurst = now - this.lastEdit < BURST_GAP_MS;
    this.lastEdit = now;
    if (inBurst && !this.reduced) {
      this.reduced = true;
      this.apply(BURST_SCALE);
    }
    if (!this.reduced || this.held) return;
    if (this.restore !== null) this.timer.clear(this.restore);
    this.restore = this.timer.set(() => this.settle(), BURST_GAP_MS);
  }

  /** Whether the view is held coarse (`hold`). */
  get holding(): boolean {
    return this.held;
  }

  /** Draws coarse until let go (`held` false: then sharp at once). */
  hold(held: boolean): void {
    if (held === this.held) return;
    this.held = held;
    if (this.restore !== null) this.timer.clear(this.restore);
    this.restore = null;
    if (held && !this.reduced) {
      this.reduced = true;
      this.apply(BURST_SCALE);
    } else if (!held && this.reduced) {
      this.settle();
    }
  }

  dispose(): void {
    if (this.restore !== null) this.timer.clear(this.restore);
    this.restore = null;
  }

  private settle(): void {
    this.restore = null;
    this.reduced = false;
    this.apply(1);
  }
}
