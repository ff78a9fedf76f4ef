import type { ReactiveControllerHost } from 'lit';
import { GuideRegistry } from './guide-host.ts';
import { guideRect, type GuideStage, type ScreenBox } from './guide-targets.ts';

/**
 * The hint ring of the lab: knows the guide hosts inside the lab (they announce themselves)
 * and follows the quest engine's ring target. A new target is revealed once (its section
 * opened, scrolled into view); rt-guide-ring then asks `locate` on every frame.
 */
export class GuideRingDriver {
  /** Where the ring is now; null: no ring. */
  locate: (() => ScreenBox | null) | null = null;
  private readonly registry: GuideRegistry;
  private target: string | null = null;

  constructor(
    private readonly host: ReactiveControllerHost & HTMLElement,
    /** The 3D view's part of finding a target: projection, canvas and scene. */
    private readonly view: () => Omit<GuideStage, 'elements'>,
  ) {
    this.registry = new GuideRegistry(host);
  }

  /** The elements on the page that carry the guide id `id`. */
  elements(id: string): Element[] {
    return this.registry.elements(id);
  }

  /** The box the ring would go around for `target` now, or null when it is not on screen. */
  rect(target: string): ScreenBox | null {
    return guideRect(target, { ...this.view(), elements: (id) => this.registry.elements(id) });
  }

  /** Opens and scrolls to the ringed control again (it was hidden when the ring came: a small screen's column showed the tasks). */
  reveal(): void {
    if (this.target) this.registry.reveal(this.target);
  }

  /** Rings `target` from now on (null: no ring). */
  follow(target: string | null): void {
    if (target === this.target) return;
    this.target = target;
    this.locate = target ? () => this.rect(target) : null;
    if (target) {
      this.registry.reveal(target);
      // A section just opened lays out on its next render: scroll once more when it has.
      setTimeout(() => this.registry.reveal(target), 150);
    }
    this.host.requestUpdate();
  }
}
