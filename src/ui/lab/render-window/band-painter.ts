import { DITHER_PERIOD, renderImageData } from '../../../render/image-data.ts';
import type { PreviewImage, RenderChanges, RenderImage } from '../../../render/render-job.ts';
import type { Tile } from '../../../tracer/tile.ts';
import type { Size } from './image-zoom.ts';
import { shrinkPiece } from './shrink-piece.ts';

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
 * and only what changed. The canvas is as large as the image is shown (canvasSizeFor), never
 * larger than the image: at the image's own size the pixels are put exactly; smaller, each
 * piece puts the canvas pixels it touches, each the mean of the image under it (shrinkPiece).
 * It paints:
 *
 * - a coarse preview at its own resolution (one pixel per block), quantized into a canvas of
 *   that size and drawn scaled up onto the visible one, its new rows only: pasting a 4096²
 *   render's previews at full resolution and quantizing all of their pixels kept the page
 *   busy for seconds while the picture stayed black on SwiftShader;
 * - the tiles of the full-resolution image as they arrive, each exactly its own rectangle, so
 *   the preview shows around them until the pass covers it;
 * - a whole image (the finished one shown again), in bands of rows.
 *
 * A new canvas size (a zoom, a resized window) paints all of that again, over the old canvas
 * scaled and the preview, so the picture never goes black meanwhile.
 *
 * With nothing left to paint it stops, so there is no per-frame work while nothing happens.
 */
export class BandPainter {
  private image: RenderImage | null = null;
  private dithering = false;
  /** Whether all of the image is to be shown (a finished render), not only its tiles. */
  private whole = false;
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
  /** The tiles of this image already on the canvas: a new canvas size paints them again. */
  private painted: Tile[] = [];
  /**
   * Which image pixels hold traced values (1), for a canvas smaller than the image: its pixels
   * average only those. Null until needed, and for a finished image (all of them do).
   */
  private rendered: Uint8Array | null = null;
  /** A new image: the canvas still shows the last one and is cleared first. */
  private clear = false;
  private frame = 0;

  /**
   * @param canvas The canvas to paint (none while the window is not drawn).
   * @param canvasSize The canvas size to show an image at: its own or smaller (canvasSizeFor).
   */
  constructor(
    private readonly canvas: () => HTMLCanvasElement | undefined,
    private readonly canvasSize: (image: Size) => Size,
  ) {}

  /** The whole of `image` is to be shown (a finished render). */
  paint(image: RenderImage, dithering: boolean): void {
    this.take(image, dithering);
    this.whole = true;
    this.rendered = null;
    [this.from, this.to] = [0, image.height];
    this.tiles = [];
    this.painted = [];
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

  /** The image is shown at another size: the next frame paints it into a canvas of that size. */
  resize(): void {
    if (this.image) this.schedule();
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
    this.painted = [];
    this.rendered = null;
    this.whole = false;
    this.from = this.to = 0;
    this.clear = false;
  }

  /** A different image (or dithering) than the one painted starts over on a cleared canvas. */
  private take(image: RenderImage, dithering: boolean): void {
    if (image.rgb === this.image?.rgb && dithering === this.dithering) return;
    this.clear = true;
    this.image = image;
    this.dithering = dithering;
    this.whole = false;
    this.rendered = null;
    this.from = this.to = 0;
    this.preview = null;
    this.tiles = [];
    this.painted = [];
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
    const size = this.canvasSize(image);
    if (canvas.width !== size.width || canvas.height !== size.height) this.resizeCanvas(canvas, context, image, size);
    else if (this.clear) context.clearRect(0, 0, canvas.width, canvas.height);
    this.clear = false;
    const start = performance.now();
    const inBudget = () => performance.now() - start < FRAME_BUDGET_MS;
    while (this.preview && this.previewFrom < this.previewTo && inBudget()) this.drawPreviewBand(context, this.preview, image);
    while (this.tiles.length > 0 && inBudget()) {
      const tile = this.tiles.shift()!;
      this.drawTile(context, image, tile);
      this.painted.push(tile);
    }
    this.from -= this.from % DITHER_PERIOD; // bands start at a multiple of the dither period
    this.to = Math.min(this.to, image.height);
    while (this.from < this.to && inBudget()) {
      const toRow = Math.min(this.to, this.from + bandRows(image.width));
      if (isFullSize(context, image)) context.putImageData(renderImageData(image, this.dithering, this.from, toRow), 0, this.from);
      else this.putShrunk(context, image, { x: 0, y: this.from, width: image.width, height: toRow - this.from });
      this.from = toRow;
    }
    if ((this.preview && this.previewFrom < this.previewTo) || this.tiles.length > 0 || this.from < this.to) this.schedule();
  };

  /**
   * Gives the canvas its new size, which clears it, and paints again what it showed: the old
   * canvas scaled as the ground, the running preview's rows drawn so far over it, then again
   * every tile and, for a finished image, every row. A new image has nothing to keep (it
   * starts on a cleared canvas).
   */
  private resizeCanvas(canvas: HTMLCanvasElement, context: CanvasRenderingContext2D, image: RenderImage, size: Size): void {
    const old = this.clear ? null : copyOf(canvas);
    [canvas.width, canvas.height] = [size.width, size.height];
    if (!old) return;
    // Smooth when shrinking; when growing, pixels as squares until painted again, as a zoom shows them.
    context.imageSmoothingEnabled = size.width < old.width;
    context.drawImage(old, 0, 0, size.width, size.height);
    const own = this.previewCanvas;
    if (this.preview && own?.width === this.preview.width && own.height === this.preview.height) this.drawPreviewRows(context, this.preview, image, 0, this.preview.height);
    // A later pass paints the same tiles again: each once is enough.
    const queued = new Map([...this.painted, ...this.tiles].map((tile) => [`${tile.x},${tile.y},${tile.width},${tile.height}`, tile]));
    this.tiles = [...queued.values()];
    this.painted = [];
    if (this.whole) [this.from, this.to] = [0, image.height];
  }

  /** The preview's next band of rows, into its own canvas and from there scaled up onto the visible one. */
  private drawPreviewBand(context: CanvasRenderingContext2D, preview: PreviewImage, image: RenderImage): void {
    let own = this.previewCanvas;
    if (!own || own.width !== preview.width || own.height !== preview.height) own = this.previewCanvas = new OffscreenCanvas(preview.width, preview.height);
    const from = this.previewFrom - (this.previewFrom % DITHER_PERIOD);
    const to = Math.min(this.previewTo, preview.height, from + bandRows(preview.width));
    own.getContext('2d')!.putImageData(renderImageData(preview, this.dithering, from, to), 0, from);
    this.drawPreviewRows(context, preview, image, from, to);
    this.previewFrom = to;
  }

  /** Rows [from, to) of the preview's own canvas, each block as the image pixels it stands for, at the canvas's scale. */
  private drawPreviewRows(context: CanvasRenderingContext2D, preview: PreviewImage, image: RenderImage, from: number, to: number): void {
    const { block } = preview;
    const scaleX = context.canvas.width / image.width;
    const scaleY = context.canvas.height / image.height;
    const top = Math.round(from * block * scaleY);
    // Blocks as blocks, as the worker filled them (no blur between the samples).
    context.imageSmoothingEnabled = false;
    context.drawImage(this.previewCanvas!, 0, from, preview.width, to - from, 0, top, Math.round(preview.width * block * scaleX), Math.round(to * block * scaleY) - top);
  }

  /** The canvas pixels that the image's rectangle `piece` touches, on a canvas smaller than the image (shrinkPiece). */
  private putShrunk(context: CanvasRenderingContext2D, image: RenderImage, piece: Tile): void {
    const { x, y, pixels, part } = shrinkPiece(image, this.rendered, context.canvas, this.dithering, piece);
    context.putImageData(pixels, x, y, part.x, part.y, part.width, part.height);
  }

  /**
   * One tile of the image. On a canvas of the image's size exactly its rectangle: quantized
   * from the multiples of the dither period at or before its corner, so the pattern matches
   * the whole image's, and put without those extra rows and columns (they may not be rendered
   * yet). On a smaller canvas, marked as traced and the canvas pixels it touches put again.
   */
  private drawTile(context: CanvasRenderingContext2D, image: RenderImage, tile: Tile): void {
    const { x, y, width, height } = tile;
    if (!isFullSize(context, image)) {
      markRendered((this.rendered ??= new Uint8Array(image.width * image.height)), image.width, tile);
      this.putShrunk(context, image, tile);
      return;
    }
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

const isFullSize = ({ canvas }: CanvasRenderingContext2D, image: RenderImage) => canvas.width === image.width && canvas.height === image.height;

/** Marks the image pixels of `tile` in `rendered` (one byte per pixel, rows `width` long). */
function markRendered(rendered: Uint8Array, width: number, { x, y, width: tileWidth, height }: Tile): void {
  for (let row = y; row < y + height; row++) rendered.fill(1, row * width + x, row * width + x + tileWidth);
}

/** A copy of what `canvas` shows, to draw from after it is resized (which clears it). */
function copyOf(canvas: HTMLCanvasElement): OffscreenCanvas {
  const copy = new OffscreenCanvas(canvas.width, canvas.height);
  copy.getContext('2d')!.drawImage(canvas, 0, 0);
  return copy;
}
