/**
 * Passes on at most one value per animation frame, the latest (for `input` events while a
 * slider or colour picker is dragged: the display refreshes once a frame anyway, so more
 * would only flood the store and the ray tracer with changes nobody sees).
 */
export class FrameThrottle<T> {
  private pending: { value: T } | null = null;
  private frame = 0;

  constructor(private readonly send: (value: T) => void) {}

  /** Sends `value` on the next frame, replacing any value still waiting. */
  push(value: T): void {
    this.pending = { value };
    if (!this.frame) this.frame = requestAnimationFrame(() => this.flush());
  }

  /** Drops a waiting value (a commit replaces it, or the element left the page). */
  cancel(): void {
    if (this.frame) cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.pending = null;
  }

  private flush(): void {
    const pending = this.pending;
    this.frame = 0;
    this.pending = null;
    if (pending) this.send(pending.value);
  }
}
