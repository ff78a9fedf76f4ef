import { msg } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { ScreenBox } from './guide-targets.ts';
import { styleMap } from 'lit/directives/style-map.js';

/** Space between the control and the ring, so the ring never hides the control's edge. */
const GAP_PX = 6;

/**
 * @summary The guidance ring (the hint ladder's second rung): a pulsing ring, in a fixed
 * overlay, around the box `locate` returns. It stays on its control through scrolling,
 * resizing, panels opening and closing and re-renders: while shown it asks `locate` again on
 * every animation frame (and at once on any scroll or resize); `locate` looks the element
 * up afresh each time, so an element rendered anew is found again. Nothing runs while no
 * ring is shown. With reduced motion the ring is a thick, still outline.
 */
export class RtGuideRing extends LocalizedElement {
  static override properties = { locate: { attribute: false }, box: { state: true } };
  static override styles = css`
    :host {
      position: fixed;
      inset: 0;
      pointer-events: none;
      z-index: 50;
    }
    .ring {
      position: fixed;
      box-sizing: border-box;
      border: 3px solid var(--rt-warning);
      border-radius: 12px;
      box-shadow:
        0 0 0 3px color-mix(in srgb, var(--rt-surface) 80%, transparent),
        0 0 16px 4px color-mix(in srgb, var(--rt-warning) 60%, transparent);
      animation: pulse 1.2s ease-in-out infinite;
    }
    @keyframes pulse {
      0%,
      100% {
        transform: scale(1);
        opacity: 1;
      }
      50% {
        transform: scale(1.06);
        opacity: 0.6;
      }
    }
    @media (prefers-reduced-motion: reduce) {
      .ring {
        animation: none;
        border-width: 5px;
      }
    }
  `;

  /** Where the target is now, in viewport px; null while it is not on the page. Null `locate`: no ring. */
  declare locate: (() => ScreenBox | null) | null;
  declare private box: ScreenBox | null;
  private frame = 0;
  private readonly follow = () => this.measure();

  constructor() {
    super();
    this.locate = null;
    this.box = null;
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.stop();
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    if (!changed.has('locate')) return;
    this.stop();
    this.box = null;
    if (!this.locate) return;
    addEventListener('scroll', this.follow, { capture: true, passive: true });
    addEventListener('resize', this.follow);
    const loop = () => {
      this.measure();
      this.frame = requestAnimationFrame(loop);
    };
    loop();
  }

  private stop(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    removeEventListener('scroll', this.follow, { capture: true });
    removeEventListener('resize', this.follow);
  }

  private measure(): void {
    const box = this.locate?.() ?? null;
    const same = box && this.box && box.left === this.box.left && box.top === this.box.top && box.width === this.box.width && box.height === this.box.height;
    if (!same && (box || this.box)) this.box = box;
  }

  override render() {
    const box = this.box;
    if (!box) return nothing;
    return html`<div
      class="ring"
      role="img"
      aria-label=${msg('Look here')}
      data-testid="guide-ring"
      style=${styleMap({
        left: `${box.left - GAP_PX}px`,
        top: `${box.top - GAP_PX}px`,
        width: `${box.width + 2 * GAP_PX}px`,
        height: `${box.height + 2 * GAP_PX}px`,
      })}
    ></div>`;
  }
}

customElements.define('rt-guide-ring', RtGuideRing);

declare global {
  interface HTMLElementTagNameMap {
    'rt-guide-ring': RtGuideRing;
  }
}
