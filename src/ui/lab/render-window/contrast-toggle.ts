import { msg, str } from '@lit/localize';
import { html, nothing, type ReactiveController, type ReactiveControllerHost } from 'lit';
import { createRef, ref } from 'lit/directives/ref.js';
import { renderImageData } from '../../../render/image-data.ts';
import type { RenderImage } from '../../../render/render-job.ts';
import { type LevelRange, levelRange, stretchContrast } from './contrast-stretch.ts';

/** The finished image and whether it was dithered: what a stretch is made from. */
export interface FinishedImage {
  image: RenderImage;
  dithering: boolean;
}

/**
 * The render window's "Stretch contrast" switch (key C, guide id render.contrast): the
 * finished image with its own darkest level shown black and its brightest white
 * (contrast-stretch.ts), so bands one level apart become visible on screen. The stretched
 * picture is a canvas of its own that takes the traced canvas's place in the viewer, so
 * zoom and comparison work on it as on the image; the image and a saved PNG are untouched.
 */
export class ContrastToggle implements ReactiveController {
  on = false;
  /** The levels of the image now stretched; null while there is none. */
  private range: LevelRange | null = null;
  private source: RenderImage | null = null;
  private readonly canvas = createRef<HTMLCanvasElement>();

  constructor(
    private readonly host: ReactiveControllerHost,
    private readonly finished: () => FinishedImage | null,
  ) {
    host.addController(this);
  }

  toggle(): void {
    this.on = !this.on;
    this.host.requestUpdate();
  }

  /** Where the traced canvas goes: out of the viewer while the stretched one stands in. */
  get tracedSlot(): string {
    return this.on && this.range ? 'unstretched' : 'traced';
  }

  hostUpdated(): void {
    const finished = this.on ? this.finished() : null;
    const canvas = this.canvas.value;
    if (!finished) {
      if (this.range) [this.range, this.source] = [null, null];
      else return;
    } else if (finished.image !== this.source && canvas) {
      const pixels = renderImageData(finished.image, finished.dithering);
      this.range = levelRange(pixels.data);
      canvas.width = pixels.width;
      canvas.height = pixels.height;
      canvas.getContext('2d')?.putImageData(new ImageData(stretchContrast(pixels.data, this.range) as Uint8ClampedArray<ArrayBuffer>, pixels.width, pixels.height), 0, 0);
      this.source = finished.image;
    } else {
      return;
    }
    this.host.requestUpdate();
  }

  /** The switch, and which levels the stretch spreads over 0–255 while it is on: for the viewer's toolbar. */
  control() {
    const range = this.on ? this.range : null;
    return html`<span slot="tools" class="group">
      <label class="toggle" data-guide="render.contrast" title=${msg('Show the image’s darkest level as black and its brightest as white, so steps of one level stand out (C). The saved image is not changed.')}>
        <input type="checkbox" .checked=${this.on} @change=${() => this.toggle()} /><span>${msg('Stretch contrast')}</span>
      </label>
      ${range ? html`<span class="group-label" role="status">${msg(str`Levels ${range.low}–${range.high} shown as 0–255`)}</span>` : nothing}
    </span>`;
  }

  /** The stretched picture, slotted as the traced image while the switch is on. */
  stretchedCanvas() {
    return html`<canvas slot=${this.on && this.range ? 'traced' : 'stretched'} ${ref(this.canvas)} role="img" aria-label=${msg('The ray traced image with stretched contrast')}></canvas>`;
  }
}
