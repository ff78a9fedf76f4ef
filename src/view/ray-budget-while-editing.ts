import { type BurstTimer, browserTimer } from './burst-resolution.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import { editBudgetFor, tracesOneSample } from './ray-budget.ts';

/**
 * How long after the last settled edit (a slider let go, a key pressed, a value typed) all
 * rays are drawn again. Longer than BurstResolution's gap: on SwiftShader a frame of all of
 * 27,784 rays took 1.5–2.7 s, and the next edit waits for it, so a learner stepping a slider
 * with the arrow keys every few tenths of a second should not get one between the steps.
 */
export const SETTLE_MS = 1000;

/**
 * How long a value the learner is still dragging through (the store's `live`) holds the
 * budget without a further edit: the drag's settled value normally ends it first, when the
 * slider is let go, and the learner may hold it still for a while in between.
 */
export const HELD_MS = 5000;

/**
 * When the ray budget (ray-budget.ts) holds: from the first edit of the scene or the ray
 * options until the edits stop. It starts with the first edit, not the second as the coarse
 * drawing does (BurstResolution): the edit's rays come after it, and a single step drawn with
 * all of 100,000 rays would hold the view for seconds before the next step could show.
 */
export class RayBudgetWhileEditing {
  private editing = false;
  /** Whether the last edit was a value still being dragged (the budget then waits HELD_MS). */
  private dragging = false;
  private settle: unknown = null;

  /**
   * `apply()` is called whenever the budget starts or ends; `screen()` is the screen shown
   * now, whose rays decide how many are drawn while it holds (editBudgetFor).
   */
  constructor(
    private readonly apply: () => void,
    private readonly timer: BurstTimer = browserTimer,
    private readonly screen: () => ScreenRays | null = () => null,
  ) {}

  /** The budget the next edit brings. */
  get editBudget(): number {
    return editBudgetFor(this.screen());
  }

  /** The budget in force now, or null: all rays are drawn. */
  get budget(): number | null {
    return this.editing ? this.editBudget : null;
  }

  /** Whether the worker traces each pixel from one sample under the budget in force (ray-budget.ts). */
  get oneSample(): boolean {
    return this.editing && tracesOneSample(this.editBudget);
  }

  /** The scene or the ray options were changed now; `live` while the learner still drags the value. */
  edited(live: boolean): void {
    if (!this.editing) {
      this.editing = true;
      this.apply();
    }
    this.dragging = live;
    if (this.settle !== null) this.timer.clear(this.settle);
    this.settle = this.timer.set(() => this.stopped(), live ? HELD_MS : SETTLE_MS);
  }

  /** A drag was let go on the value it had reached (its settled value changed nothing): the edits stop as after any settled one. */
  letGo(): void {
    if (this.dragging) this.edited(false);
  }

  dispose(): void {
    if (this.settle !== null) this.timer.clear(this.settle);
    this.settle = null;
  }

  private stopped(): void {
    this.settle = null;
    this.editing = false;
    this.dragging = false;
    this.apply();
  }
}
