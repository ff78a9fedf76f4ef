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
 * The share a heavy screen's edits draw at (the rays thinned to HEAVY_EDIT_RAYS, ray-budget.ts):
 * an eighth of the pixels. With the free lab's largest settings each step of a drag waited
 * for SwiftShader's frame of the page, the view's part of it included, and this scale brought
 * the drag's 95th percentile under 100 ms (figures: docs/benchmark-log.md, issue 38). It is
 * visibly coarser, so a lighter screen (every level's) keeps BURST_SCALE.
 */
export const HEAVY_BURST_SCALE = 0.35;

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
 * While the rays are held to a budget (`hold`, view/ray-budget.ts) the view draws coarse (at
 * the scale the hold asks) from the first edit and stays so between edits: there a sharp frame
 * of many rays is slow on SwiftShader, and each switch between sharp and coarse waits for the
 * frame before it, so steps a few tenths of a second apart waited far longer than a step
 * (docs/benchmark-log.md, issue 38). Let go, it is drawn sharp at once, with every ray.
 */
export class BurstResolution {
  private lastEdit = -Infinity;
  private restore: unknown = null;
  /** The scale a hold asks (`hold`), or null: not held. */
  private held: number | null = null;
  /** The share of the pixel ratio drawn now (1: full resolution). */
  private scale = 1;

  /** `apply(scale)` redraws the view at `scale` × its pixel ratio (1: full resolution). */
  constructor(
    private readonly apply: (scale: number) => void,
    private readonly timer: BurstTimer = browserTimer,
  ) {}

  /** Whether the view draws at reduced resolution now. */
  get reducing(): boolean {
    return this.scale !== 1;
  }

  /** The scene was edited now. */
  edited(): void {
    const now = this.timer.now();
    const inBurst = now - this.lastEdit < BURST_GAP_MS;
    this.lastEdit = now;
    if (inBurst && !this.reducing) this.reduce(BURST_SCALE);
    if (!this.reducing || this.held !== null) return;
    if (this.restore !== null) this.timer.clear(this.restore);
    this.restore = this.timer.set(() => this.settle(), BURST_GAP_MS);
  }

  /** Whether the view is held coarse (`hold`). */
  get holding(): boolean {
    return this.held !== null;
  }

  /** Draws at `scale` × the pixel ratio until let go (`null`: then sharp at once). */
  hold(scale: number | null): void {
    if (scale === this.held) return;
    this.held = scale;
    if (this.restore !== null) this.timer.clear(this.restore);
    this.restore = null;
    if (scale !== null && scale !== this.scale) this.reduce(scale);
    else if (scale === null && this.reducing) this.settle();
  }

  dispose(): void {
    if (this.restore !== null) this.timer.clear(this.restore);
    this.restore = null;
  }

  private reduce(scale: number): void {
    this.scale = scale;
    this.apply(scale);
  }

  private settle(): void {
    this.restore = null;
    this.scale = 1;
    this.apply(1);
  }
}
