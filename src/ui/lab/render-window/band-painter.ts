import { DITHER_PERIOD, renderImageData } from '../../../render/image-data.ts';
import type { PreviewImage, RenderChanges, RenderImage } from '../../../render/render-job.ts';
import { PLAIN_QUANTIZATION, type Quantization } from '../../../tracer/quantize.ts';
import type { Tile } from '../../../tracer/tile.ts';
import { type LevelRange, stretchContrast } from './contrast-stretch.ts';
import { type CanvasView, pixelsCovering, type Rect, sameView, type Size } from './image-zoom.ts';
import { shrinkPiece } from './shrink-piece.ts';

/**
 * Main-thread time a repaint may take per frame. Quantizing a whole 2048 × 1536 image takes
 * about 90 ms (measured in Chromium), which would stall the page while the workers trace; in
 * bands within this budget the page keeps responding (the lab's "never blocked > 50 ms").
 */
const FRAME_BUDGET_MS = 8;

/** Pixels per band: about 2 ms of quantizing, so a frame rarely overruns its budget by much. */
const BAND_PIXELS = 65_536;

/** Rows per band of an image (or a part of it) `width` wide: a multiple of the dither pattern's period (renderImageData). */
const bandRows = (width: number) => Math.max(DITHER_PERIOD, Math.floor(BAND_PIXELS / width / DITHER_PERIOD) * DITHER_PERIOD);

/**
 * Paints a render into a canvas over as many frames as it needs, within a budget per frame,
 * and only what changed. The canvas holds the part of the image on screen (a CanvasView from
 * the viewer) at one canvas pixel per device pixel at most: at the image's own scale the
 * pixels are put exactly; smaller, each piece puts the canvas pixels it touches, each the
 * mean of the image under it (shrinkPiece). It paints:
 *
 * - a coarse preview at its own resolution (one pixel per block), quantized into a canvas of
 *   that size and drawn scaled up onto the visible one, its new rows only: pasting a 4096²
 *   render's previews at full resolution and quantizing all of their pixels kept the page
 *   busy for seconds while the picture stayed black on SwiftShader;
 * - the tiles of the full-resolution image as they arrive, each exactly its own rectangle, so
 *   the preview shows around them until the pass covers it;
 * - a whole image (the finished one shown again), in bands of rows.
 *
 * A new view (a zoom, a scroll, a resized window) or contrast stretch paints what is on
 * screen again, over the old canvas moved to its new place (and the preview), so the picture
 * never goes black meanwhile.
 *
 * With nothing left to paint it stops, so there is no per-frame work while nothing happens.
 */
export class BandPainter {
  private image: RenderImage | null = null;
  /** How the image is quantized: the rendered scene's dithering and encoding. */
  private quantization: Quantization = PLAIN_QUANTIZATION;
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
  /** The tiles of this image already painted: a new view paints them again. */
  private painted: Tile[] = [];
  /**
   * Which image pixels hold traced values (1): a canvas smaller than the image averages only
   * those. Null for a finished image (all of them do).
   */
  private rendered: Uint8Array | null = null;
  /** The view the canvas holds; null before the first frame. */
  private shown: CanvasView | null = null;
  /** The contrast stretch applied to what is painted (ContrastToggle), or none. */
  private stretch: LevelRange | null = null;
  /** A new image: the canvas still shows the last one and is cleared first. */
  private clear = false;
  private frame = 0;

  /**
   * @param canvas The canvas to paint (none while the window is not drawn).
   * @param view What the canvas is to show of an image of that size (the viewer's tracedView).
   */
  constructor(
    private readonly canvas: () => HTMLCanvasElement | undefined,
    private readonly view: (image: Size) => CanvasView,
  ) {}

  /** The whole of `image` is to be shown (a finished render). */
  paint(image: RenderImage, quantization: Quantization): void {
    this.take(image, quantization);
    this.whole = true;
    this.rendered = null;
    [this.from, this.to] = [0, image.height];
    this.tiles = [];
    this.painted = [];
    this.preview = null;
    this.schedule();
  }

  /** A running render's `changes` to `image` (its full-resolution picture): see the class comment. */
  paintChanges(image: RenderImage, changes: RenderChanges, quantization: Quantization): void {
    this.take(image, quantization);
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
    const rendered = (this.rendered ??= new Uint8Array(image.width * image.height));
    for (const tile of changes.tiles) markRendered(rendered, image.width, tile);
    this.tiles.push(...changes.tiles);
    this.schedule();
  }

  /** The viewer shows another part of the image, or at another scale: the next frame paints that. */
  reframe(): void {
    if (this.image) this.schedule();
  }

  /** The image's levels stretched by `range` from now on (null: as they are); what is on screen is painted again. */
  setStretch(range: LevelRange | null): void {
    if (range?.low === this.stretch?.low && range?.high === this.stretch?.high) return;
    this.stretch = range;
    if (!this.image) return;
    this.paintAgain();
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
    this.painted = [];
    this.rendered = null;
    this.whole = false;
    this.from = this.to = 0;
    this.clear = false;
  }

  /** A different image (or quantization) than the one painted starts over on a cleared canvas. */
  private take(image: RenderImage, quantization: Quantization): void {
    const { dithering, encoding } = this.quantization;
    if (image.rgb === this.image?.rgb && quantization.dithering === dithering && quantization.encoding === encoding) return;
    this.clear = true;
    this.image = image;
    this.quantization = quantization;
    this.whole = false;
    this.rendered = null;
    this.from = this.to = 0;
    this.preview = null;
    this.tiles = [];
    this.painted = [];
  }

  /** Everything painted so far is to be painted again (each tile once: a later pass paints the same tiles again). */
  private paintAgain(): void {
    const queued = new Map([...this.painted, ...this.tiles].map((tile) => [`${tile.x},${tile.y},${tile.width},${tile.height}`, tile]));
    this.tiles = [...queued.values()];
    this.painted = [];
    if (this.whole) [this.from, this.to] = [0, this.image!.height];
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
    const view = this.view(image);
    if (this.clear) {
      // A new image: nothing of the old one to keep.
      if (canvas.width !== view.window.width || canvas.height !== view.window.height) [canvas.width, canvas.height] = [view.window.width, view.window.height];
      else context.clearRect(0, 0, canvas.width, canvas.height);
      this.shown = view;
      this.clear = false;
    } else if (!sameView(view, this.shown)) {
      this.moveTo(canvas, context, image, view);
    }
    const start = performance.now();
    const inBudget = () => performance.now() - start < FRAME_BUDGET_MS;
    while (this.preview && this.previewFrom < this.previewTo && inBudget()) this.drawPreviewBand(context, this.preview, image, view);
    const onScreen = imagePart(view, image);
    while (this.tiles.length > 0 && inBudget()) {
      const tile = this.tiles.shift()!;
      this.drawPiece(context, image, view, onScreen, tile);
      this.painted.push(tile);
    }
    this.to = Math.min(this.to, image.height);
    while (this.from < this.to && inBudget()) {
      const toRow = Math.min(this.to, this.from + bandRows(onScreen.width));
      this.drawPiece(context, image, view, onScreen, { x: 0, y: this.from, width: image.width, height: toRow - this.from });
      this.from = toRow;
    }
    if ((this.preview && this.previewFrom < this.previewTo) || this.tiles.length > 0 || this.from < this.to) this.schedule();
  };

  /**
   * Makes the canvas hold `view` instead of the one it holds: sized to its window (which
   * clears it), the old canvas drawn where its pixels now belong as the ground, the running
   * preview's rows drawn so far over it, and everything painted queued to be painted again.
   */
  private moveTo(canvas: HTMLCanvasElement, context: CanvasRenderingContext2D, image: RenderImage, view: CanvasView): void {
    const before = this.shown!;
    const old = copyOf(canvas);
    [canvas.width, canvas.height] = [view.window.width, view.window.height];
    this.shown = view;
    const scaleX = view.full.width / before.full.width;
    const scaleY = view.full.height / before.full.height;
    // Smooth when shrinking; when growing, pixels as squares until painted again, as a zoom shows them.
    context.imageSmoothingEnabled = scaleX < 1;
    context.drawImage(
      old,
      before.window.x * scaleX - view.window.x,
      before.window.y * scaleY - view.window.y,
      before.window.width * scaleX,
      before.window.height * scaleY,
    );
    const own = this.previewCanvas;
    if (this.preview && own?.width === this.preview.width && own.height === this.preview.height)
      this.drawPreviewRows(context, this.preview, image, view, 0, this.preview.height);
    this.paintAgain();
  }

  /** The preview's next band of rows, into its own canvas and from there scaled up onto the visible one. */
  private drawPreviewBand(context: CanvasRenderingContext2D, preview: PreviewImage, image: RenderImage, view: CanvasView): void {
    let own = this.previewCanvas;
    if (!own || own.width !== preview.width || own.height !== preview.height) own = this.previewCanvas = new OffscreenCanvas(preview.width, preview.height);
    const from = this.previewFrom - (this.previewFrom % DITHER_PERIOD);
    const to = Math.min(this.previewTo, preview.height, from + bandRows(preview.width));
    own.getContext('2d')!.putImageData(renderImageData(preview, this.quantization, from, to), 0, from);
    this.drawPreviewRows(context, preview, image, view, from, to);
    this.previewFrom = to;
  }

  /** Rows [from, to) of the preview's own canvas, each block as the image pixels it stands for, in the view. */
  private drawPreviewRows(context: CanvasRenderingContext2D, preview: PreviewImage, image: RenderImage, view: CanvasView, from: number, to: number): void {
    const { block } = preview;
    const scaleX = view.full.width / image.width;
    const scaleY = view.full.height / image.height;
    const top = Math.round(from * block * scaleY);
    // Blocks as blocks, as the worker filled them (no blur between the samples).
    context.imageSmoothingEnabled = false;
    context.drawImage(
      this.previewCanvas!,
      0,
      from,
      preview.width,
      to - from,
      -view.window.x,
      top - view.window.y,
      Math.round(preview.width * block * scaleX),
      Math.round(to * block * scaleY) - top,
    );
  }

  /**
   * The part of the image's rectangle `piece` (a tile, or a band of rows) that is on screen
   * (`onScreen`: the image pixels of the view's window).
   * At the image's own scale exactly its pixels: quantized from the multiples of the dither
   * period at or before its corner, so the pattern matches the whole image's, and put
   * without those extra rows and columns (they may not be rendered yet). Smaller, the canvas
   * pixels it touches (shrinkPiece).
   */
  private drawPiece(context: CanvasRenderingContext2D, image: RenderImage, view: CanvasView, onScreen: Rect, piece: Tile): void {
    const part = overlap(piece, onScreen);
    if (!part) return;
    const { x: offsetX, y: offsetY } = view.window;
    if (view.full.width !== image.width || view.full.height !== image.height) {
      const shrunk = shrinkPiece(image, this.rendered, view.full, this.quantization, part);
      context.putImageData(
        this.stretched(shrunk.pixels),
        shrunk.x - offsetX,
        shrunk.y - offsetY,
        shrunk.part.x,
        shrunk.part.y,
        shrunk.part.width,
        shrunk.part.height,
      );
      return;
    }
    const { x, y, width, height } = part;
    const left = x - (x % DITHER_PERIOD);
    const top = y - (y % DITHER_PERIOD);
    const rect = { width: x + width - left, height: y + height - top, rgb: new Float32Array((x + width - left) * (y + height - top) * 3) };
    for (let row = 0; row < rect.height; row++) {
      const from = ((top + row) * image.width + left) * 3;
      rect.rgb.set(image.rgb.subarray(from, from + rect.width * 3), row * rect.width * 3);
    }
    context.putImageData(this.stretched(renderImageData(rect, this.quantization)), left - offsetX, top - offsetY, x - left, y - top, width, height);
  }

  private stretched(pixels: ImageData): ImageData {
    if (!this.stretch) return pixels;
    return new ImageData(stretchContrast(pixels.data, this.stretch) as Uint8ClampedArray<ArrayBuffer>, pixels.width, pixels.height);
  }
}

/** The image pixels the view's window shows (partly or wholly). */
function imagePart({ full, window }: CanvasView, image: Size): Rect {
  const [left, right] = pixelsCovering(window.x, window.x + window.width, image.width / full.width, image.width);
  const [top, bottom] = pixelsCovering(window.y, window.y + window.height, image.height / full.height, image.height);
  return { x: left, y: top, width: right - left, height: bottom - top };
}

function overlap(a: Rect, b: Rect): Rect | null {
  const x = Math.max(a.x, b.x);
  const y = Math.max(a.y, b.y);
  const width = Math.min(a.x + a.width, b.x + b.width) - x;
  const height = Math.min(a.y + a.height, b.y + b.height) - y;
  return width > 0 && height > 0 ? { x, y, width, height } : null;
}

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
