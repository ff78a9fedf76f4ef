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
 * it needs, and only the rows that changed: a render fills its image tile by tile, and
 * sweeping a whole 4096 × 4096 image after every tile kept the main thread busy with
 * quantizing (1.5 s of every 5 s, with as much again for pasting tiles, in a profile of the
 * e2e run). With nothing left to paint it stops, so there is no per-frame work while nothing
 * happens. The default 512 × 384 image takes one frame.
 */
export class BandPainter {
  private image: RenderImage | null = null;
  private dithering = false;
  /** Rows still to paint, [from, to); none when from ≥ to. */
  private from = 0;
  private to = 0;
  /** A new image: the canvas still shows the last one and is cleared first. */
  private clear = false;
  private frame = 0;

  constructor(private readonly canvas: () => HTMLCanvasElement | undefined) {}

  /**
   * The image (a new one, or the same one filled in further) is to be shown: `rows` [from, to)
   * of it changed, or all of it when not given. A new image clears the canvas first rather
   * than painting its empty rows (a 4096² sweep took seconds before the first tile showed).
   */
  paint(image: RenderImage, dithering: boolean, rows?: [number, number]): void {
    const fresh = image.rgb !== this.image?.rgb || dithering !== this.dithering;
    const [from, to] = rows ?? [0, image.height];
    this.clear ||= fresh;
    this.image = image;
    this.dithering = dithering;
    if (fresh || this.from >= this.to) [this.from, this.to] = [from, to];
    else [this.from, this.to] = [Math.min(this.from, from), Math.max(this.to, to)];
    this.frame ||= requestAnimationFrame(this.onFrame);
  }

  /** Forgets the image: nothing more is painted. */
  stop(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.image = null;
    this.from = this.to = 0;
    this.clear = false;
  }

  private readonly onFrame = (): void => {
    this.frame = 0;
    const { image, dithering } = this;
    const canvas = this.canvas();
    const context = canvas?.getContext('2d');
    if (!image || !canvas || !context) return;
    if (canvas.width !== image.width || canvas.height !== image.height) {
      canvas.width = image.width; // clears it
      canvas.height = image.height;
      // A fresh image's rows are painted as they fill in; the same one's are all repainted.
      if (!this.clear) [this.from, this.to] = [0, image.height];
    } else if (this.clear) {
      context.clearRect(0, 0, canvas.width, canvas.height);
    }
    this.clear = false;
    const bandRows = Math.max(DITHER_PERIOD, Math.floor(BAND_PIXELS / image.width / DITHER_PERIOD) * DITHER_PERIOD);
    // Bands start at a multiple of the dither pattern's period (renderImageData).
    this.from -= this.from % DITHER_PERIOD;
    this.to = Math.min(this.to, image.height);
    const start = performance.now();
    while (this.from < this.to && performance.now() - start < FRAME_BUDGET_MS) {
      const toRow = Math.min(this.to, this.from + bandRows);
      context.putImageData(renderImageData(image, dithering, this.from, toRow), 0, this.from);
      this.from = toRow;
    }
    if (this.from < this.to) this.frame = requestAnimationFrame(this.onFrame);
  };
}
