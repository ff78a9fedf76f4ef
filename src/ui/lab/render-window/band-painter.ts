import { DITHER_PERIOD, renderImageData } from '../../../render/image-data.ts';
import type { RenderImage } from '../../../render/render-job.ts';

/**
 * Main-thread time a repaint may take per frame. Quantizing a whole 2048 × 1536 image takes
 * about 90 ms (measured in Chromium), which would stall the page while the workers trace; in
 * bands within this budget the page keeps responding (the lab's "never blocked > 50 ms").
 */
const FRAME_BUDGET_MS = 8;

/** Pixels per band: about 2 ms of quantizing, so a frame rarely overruns its budget by much. */
const BAND_PIXELS = 65_536;

/**
 * Paints a render's live image into a canvas, a band of rows at a time, over as many frames as
 * it needs. A change during a sweep makes it sweep again once it reaches the bottom; with no
 * change it stops, so there is no per-frame work while nothing happens. The default 512 × 384
 * image takes one frame.
 */
export class BandPainter {
  private image: RenderImage | null = null;
  private dithering = false;
  /** The next band's first row; 0 between sweeps. */
  private nextRow = 0;
  /** The image changed since the current sweep started. */
  private dirty = false;
  private frame = 0;

  constructor(private readonly canvas: () => HTMLCanvasElement | undefined) {}

  /** The image (a new one, or the same one filled in further) is to be shown. */
  paint(image: RenderImage, dithering: boolean): void {
    if (image.rgb !== this.image?.rgb || dithering !== this.dithering) this.nextRow = 0;
    this.image = image;
    this.dithering = dithering;
    this.dirty = true;
    this.frame ||= requestAnimationFrame(this.onFrame);
  }

  /** Forgets the image: nothing more is painted. */
  stop(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.image = null;
    this.dirty = false;
    this.nextRow = 0;
  }

  private readonly onFrame = (): void => {
    this.frame = 0;
    const { image, dithering } = this;
    const canvas = this.canvas();
    const context = canvas?.getContext('2d');
    if (!image || !canvas || !context) return;
    if (canvas.width !== image.width || canvas.height !== image.height) {
      canvas.width = image.width; // clears it: start over at the top
      canvas.height = image.height;
      this.nextRow = 0;
    }
    if (this.nextRow === 0) this.dirty = false;
    const bandRows = Math.max(DITHER_PERIOD, Math.floor(BAND_PIXELS / image.width / DITHER_PERIOD) * DITHER_PERIOD);
    const start = performance.now();
    do {
      const toRow = Math.min(image.height, this.nextRow + bandRows);
      context.putImageData(renderImageData(image, dithering, this.nextRow, toRow), 0, this.nextRow);
      this.nextRow = toRow;
    } while (this.nextRow < image.height && performance.now() - start < FRAME_BUDGET_MS);
    if (this.nextRow >= image.height) {
      this.nextRow = 0;
      if (!this.dirty) return;
    }
    this.frame = requestAnimationFrame(this.onFrame);
  };
}
