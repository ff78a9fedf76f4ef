import { boxesOverlap, type GuideAndLook, renderWindowInTheWay } from './render-window-in-the-way.ts';

/**
 * Watches, for the lab, whether the open render window has come in the way of what the game
 * now needs in the 3D view (render-window-in-the-way.ts), from one update to the next.
 */
export class RenderWindowWatch {
  private last: GuideAndLook = { ring: null, look: null };

  constructor(
    /** The lab's render window element, if it is on the page. */
    private readonly window: () => Element | null,
    /** The elements that carry a guide id (none for a 3D object or a pixel: those are in the view). */
    private readonly guideElements: (target: string) => Element[],
  ) {}

  /** Whether a window open now must close for what the game shows now; remembers it for the next call. */
  mustClose(now: GuideAndLook, open: boolean): boolean {
    const inTheWay = renderWindowInTheWay(this.last, now, (ring) => this.covers(ring));
    this.last = now;
    return open && inTheWay;
  }

  /** Whether the render window hides the guide target `ring` (one with no element is in the view, under it). */
  private covers(ring: string): boolean {
    const window = this.window();
    const elements = this.guideElements(ring);
    if (!window || elements.length === 0) return true;
    const box = window.getBoundingClientRect();
    return elements.some((element) => boxesOverlap(element.getBoundingClientRect(), box));
  }
}
