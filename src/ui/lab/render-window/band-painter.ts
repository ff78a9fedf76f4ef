import { DITHER_PERIOD, renderImageData } from '../../../render/image-data.ts';
import type { PreviewImage, RenderChanges, RenderImage } from '../../../render/render-job.ts';
import type { Tile } from '../../../tracer/tile.ts';

/**
 * Main-thread time a repaint may take per frame. Quantizing a whole 2048 × 1536 image takes
 * about 90 ms (measured in Chromium), which would stall the page while the workers trace; in
 * bands within this budget the page keeps responding (the lab's "never blocked > 50 ms").
 */
const FRAME_BUDGET_MS = 8;

/** Pixels per band: about 2 ms of quantizing, so a frame rarely overruns its budget by much. */
const BAND_PIXELS = 65_536;

/** Rows per band of an image `width` wide: a multiple of the dither pattern's period (renderImageData). */
const bandRows = (width: number) => Math.max(DITHER_PERIOD, Math.floor(BAND_PIXELS / width / DITHER_PERIOD) * DITHER_PERIOD);

/**
 * Paints a render into a canvas over as many frames as it needs, within a budget per frame,
 * and only what changed:
 *
 * - a coarse preview at its own resolution (one pixel per block), quantized into a canvas of
 *   that size and drawn scaled up onto the visible one, its new rows only: pasting a 4096²
 *   render's previews at full resolution and quantizing all of their pixels kept the page
 *   busy for seconds while the picture stayed black on SwiftShader;
 * - the tiles of the full-resolution image as they arrive, each exactly its own rectangle, so
 *   the preview shows around them until the pass covers it;
 * - a whole image (the finished one shown again), in bands of rows.
 *
 * With nothing left to paint it stops, so there is no per-frame work while nothing happens.
 */
export class BandPainter {
  private image: RenderImage | null = null;
  private dithering = false;
  /** Whole-image rows still to paint, [from, to); none when from ≥ to. */
  private from = 0;
  private to = 0;
  /** The preview whose rows [previewFrom, previewTo) are still to draw. */
  private preview: PreviewImage | null = null;
  private previewFrom = 0;
  private previewTo = 0;
  /** The preview's own pixels, drawn scaled from here. */
  private previewCanvas: OffscreenCanvas | null = null;
  private tiles: Tile[] = [];
  /** A new image: the canvas still shows the last one and is cleared first. */
  private clear = false;
  private frame = 0;

  constructor(private readonly canvas: () => HTMLCanvasElement | undefined) {}

  /** The whole of `image` is to be shown (a finished render). */
  paint(image: RenderImage, dithering: boolean): void {
    this.take(image, dithering);
    [this.from, this.to] = [0, image.height];
    this.tiles = [];
    this.preview = null;
    this.schedule();
  }

  /** A running render's `changes` to `image` (its full-resolution picture): see the class comment. */
  paintChanges(image: RenderImage, changes: RenderChanges, dithering: boolean): void {
    this.take(image, dithering);
    if (changes.preview) {
      const { image: preview, rows } = changes.preview;
      // A finer preview starts as the coarser one scaled up (TiledRender): the coarser one's
      // rows not drawn yet are drawn from it, as its rows.
      const old = this.preview;
      if (old && preview !== old && this.previewFrom < this.previewTo) {
        const ratio = old.block / preview.block;
        [this.previewFrom, this.previewTo] = [this.previewFrom * ratio, Math.min(preview.height, this.previewTo * ratio)];
      } else if (preview !== old) {
        [this.previewFrom, this.previewTo] = rows;
      }
      this.preview = preview;
      [this.previewFrom, this.previewTo] = [Math.min(this.previewFrom, rows[0]), Math.max(this.previewTo, rows[1])];
    }
    this.tiles.push(...changes.tiles);
    this.schedule();
  }

  /**
   * Sets up the page's 2D drawing before a render needs it. The browser connects a page's
   * first 2D drawing to the GPU process in a synchronous round trip; made during a render it
   * waited there 190–220 ms behind the GPU process's frames (a software GPU, both cores
   * tracing), a frozen page when the first preview arrived. Made with the window's opening,
   * while the machine is idle, it takes a few ms.
   */
  warmUp(): void {
    this.previewCanvas ??= new OffscreenCanvas(1, 1);
    this.previewCanvas.getContext('2d')?.putImageData(new ImageData(1, 1), 0, 0);
  }

  /** Forgets the image: nothing more is painted. */
  stop(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.image = null;
    this.preview = null;
    this.tiles = [];
    this.from = this.to = 0;
    this.clear = false;
  }

  /** A different image (or dithering) than the one painted starts over on a cleared canvas. */
  private take(image: RenderImage, dithering: boolean): void {
    if (image.rgb === this.image?.rgb && dithering === this.dithering) return;
    this.clear = true;
    this.image = image;
    this.dithering = dithering;
    this.from = this.to = 0;
    this.preview = null;
    this.tiles = [];
  }

  private schedule(): void {
    this.frame ||= requestAnimationFrame(this.onFrame);
  }

  private readonly onFrame = (): void => {
    this.frame = 0;
    const { image } = this;
    const canvas = this.canvas();
    const context = canvas?.getContext('2d');
    if (!image || !canvas || !context) return;
    if (canvas.width !== image.width || canvas.height !== image.height) {
      canvas.width = image.width; // clears it
      canvas.height = image.height;
    } else if (this.clear) {
      context.clearRect(0, 0, canvas.width, canvas.height);
    }
    this.clear = false;
    const start = performance.now();
    const inBudget = () => performance.now() - start < FRAME_BUDGET_MS;
    while (this.preview && this.previewFrom < this.previewTo && inBudget()) this.drawPreviewBand(context, this.preview);
    while (this.tiles.length > 0 && inBudget()) this.drawTile(context, image, this.tiles.shift()!);
    this.from -= this.from % DITHER_PERIOD; // bands start at a multiple of the dither period
    this.to = Math.min(this.to, image.height);
    while (this.from < this.to && inBudget()) {
      const toRow = Math.min(this.to, this.from + bandRows(image.width));
      context.putImageData(renderImageData(image, this.dithering, this.from, toRow), 0, this.from);
      this.from = toRow;
    }
    if ((this.preview && this.previewFrom < this.previewTo) || this.tiles.length > 0 || this.from < this.to) this.schedule();
  };

  /** The preview's next band of rows, into its own canvas and from there scaled up onto the visible one. */
  private drawPreviewBand(context: CanvasRenderingContext2D, preview: PreviewImage): void {
    let own = this.previewCanvas;
    if (!own || own.width !== preview.width || own.height !== preview.height) own = this.previewCanvas = new OffscreenCanvas(preview.width, preview.height);
    const from = this.previewFrom - (this.previewFrom % DITHER_PERIOD);
    const to = Math.min(this.previewTo, preview.height, from + bandRows(preview.width));
    own.getContext('2d')!.putImageData(renderImageData(preview, this.dithering, from, to), 0, from);
    // Blocks as blocks, as the worker filled them (no blur between the samples).
    context.imageSmoothingEnabled = false;
    const { block } = preview;
    context.drawImage(own, 0, from, preview.width, to - from, 0, from * block, preview.width * block, (to - from) * block);
    this.previewFrom = to;
  }

  /**
   * One tile of the image, exactly its rectangle: quantized from the multiples of the dither
   * period at or before its corner, so the pattern matches the whole image's, and put
   * without those extra rows and columns (they may not be rendered yet).
   */
  private drawTile(context: CanvasRenderingContext2D, image: RenderImage, { x, y, width, height }: Tile): void {
    const left = x - (x % DITHER_PERIOD);
    const top = y - (y % DITHER_PERIOD);
    const rect = { width: x + width - left, height: y + height - top, rgb: new Float32Array((x + width - left) * (y + height - top) * 3) };
    for (let row = 0; row < rect.height; row++) {
      const from = ((top + row) * image.width + left) * 3;
      rect.rgb.set(image.rgb.subarray(from, from + rect.width * 3), row * rect.width * 3);
    }
    context.putImageData(renderImageData(rect, this.dithering), left, top, x - left, y - top, width, height);
  }
}
