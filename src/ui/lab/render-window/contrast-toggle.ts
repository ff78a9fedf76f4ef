import { msg, str } from '@lit/localize';
import { html, nothing, type ReactiveController, type ReactiveControllerHost } from 'lit';
import { renderImageData } from '../../../render/image-data.ts';
import type { RenderImage } from '../../../render/render-job.ts';
import type { Quantization } from '../../../tracer/quantize.ts';
import { type LevelRange, levelRange } from './contrast-stretch.ts';
import { guideIds } from '../../../quest/lab-controls.ts';

/** The finished image and how it is quantized (dithering, encoding): what a stretch is made from. */
export interface FinishedImage {
  image: RenderImage;
  quantization: Quantization;
}

/**
 * The render window's "Stretch contrast" switch (key C, guide id render.contrast): the
 * finished image with its own darkest level shown black and its brightest white
 * (contrast-stretch.ts), so bands one level apart become visible on screen. The window's
 * painter draws the stretch (BandPainter.setStretch), so zoom and comparison work on it as on
 * the image; the image and a saved PNG are untouched. It stays on across renders of one scene,
 * and goes off when another scene is loaded (a new level, the free lab, a scene file): it
 * belongs to the banding level's question, and stretched it misled the next level's first
 * render.
 */
export class ContrastToggle implements ReactiveController {
  on = false;
  /** The levels of the image now stretched; null while there is none. */
  private range: LevelRange | null = null;
  private source: RenderImage | null = null;

  /**
   * @param finished The image to stretch: the finished render on show, or none.
   * @param apply Shows the image stretched by the range, or as it is (null).
   */
  constructor(
    private readonly host: ReactiveControllerHost,
    private readonly finished: () => FinishedImage | null,
    private readonly apply: (range: LevelRange | null) => void,
  ) {
    host.addController(this);
  }

  toggle(): void {
    this.on = !this.on;
    this.host.requestUpdate();
  }

  /** Off again: a new scene (a level opens) starts with its image as it is. */
  reset(): void {
    if (!this.on) return;
    this.on = false;
    this.host.requestUpdate();
  }

  hostUpdated(): void {
    const finished = this.on ? this.finished() : null;
    if (!finished) {
      if (!this.range) return;
      [this.range, this.source] = [null, null];
    } else if (finished.image !== this.source) {
      this.range = levelRange(renderImageData(finished.image, finished.quantization).data);
      this.source = finished.image;
    } else {
      return;
    }
    this.apply(this.range);
    this.host.requestUpdate(); // the control shows the range
  }

  /** The switch, and which levels the stretch spreads over 0–255 while it is on: for the viewer's toolbar. */
  control() {
    const range = this.on ? this.range : null;
    return html`<span slot="tools" class="group">
      <label class="toggle" data-guide=${guideIds('render.contrast')} title=${msg('Show the image’s darkest level as black and its brightest as white, so steps of one level stand out (C). The saved image is not changed.')}>
        <input type="checkbox" .checked=${this.on} @change=${() => this.toggle()} /><span>${msg('Stretch contrast')}</span>
      </label>
      ${range ? html`<span class="group-label" role="status">${msg(str`Levels ${range.low}–${range.high} shown as 0–255`)}</span>` : nothing}
    </span>`;
  }
}
