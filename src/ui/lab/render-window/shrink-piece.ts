import { DITHER_PERIOD } from '../../../render/image-data.ts';
import type { RenderImage } from '../../../render/render-job.ts';
import { type Quantization, toRgba8 } from '../../../tracer/quantize.ts';
import type { Tile } from '../../../tracer/tile.ts';
import { pixelsCovering, type Rect, type Size } from './image-zoom.ts';

/** A rectangle of canvas pixels: where `pixels` go, and the part of them to put (putImageData's dirty rectangle). */
export interface ShrunkPiece {
  x: number;
  y: number;
  pixels: ImageData;
  part: Rect;
}

/** How one image pixel's span on an axis falls into canvas pixels: at most two when the canvas is smaller. */
interface Spans {
  /** The first canvas pixel it overlaps, relative to the piece's first canvas pixel. */
  first: Int32Array;
  /** How much of that canvas pixel it covers; the rest of its span (if any) covers the next. */
  share: Float64Array;
  /** Its whole span in canvas pixels (the scale). */
  span: number;
}

/** The image pixels [from, to) on an axis scaled by `scale`, relative to canvas pixel `origin`. */
function spans(from: number, to: number, scale: number, origin: number): Spans {
  const first = new Int32Array(to - from);
  const share = new Float64Array(to - from);
  for (let i = from; i < to; i++) {
    const start = i * scale;
    const cell = Math.floor(start);
    first[i - from] = cell - origin;
    share[i - from] = Math.min(scale, cell + 1 - start);
  }
  return { first, share, span: scale };
}

/**
 * The canvas pixels that the image's rectangle `piece` touches, on a canvas of `canvas` size
 * smaller than the image: each the mean of the image pixels under it, weighted by the area
 * they cover (a box filter), over the pixels `rendered` says hold a value (null: all do), so a
 * canvas pixel half on a tile not traced yet shows the traced half, not a mix with black.
 * Averaged as shown (each value clamped to 0–1, in path mode after its exposure) and quantized like the image itself
 * (toRgba8, with its dithering and encoding), dithered by canvas position: the pixels start at a multiple of the dither period
 * and `part` says which of them the piece touched.
 */
export function shrinkPiece(image: RenderImage, rendered: Uint8Array | null, canvas: Size, quantization: Quantization, piece: Tile): ShrunkPiece {
  const scaleX = canvas.width / image.width;
  const scaleY = canvas.height / image.height;
  const [touchedLeft, right] = pixelsCovering(piece.x, piece.x + piece.width, scaleX, canvas.width);
  const [touchedTop, bottom] = pixelsCovering(piece.y, piece.y + piece.height, scaleY, canvas.height);
  const left = touchedLeft - (touchedLeft % DITHER_PERIOD);
  const top = touchedTop - (touchedTop % DITHER_PERIOD);
  const [width, height] = [right - left, bottom - top];
  // The image pixels overlapping those canvas pixels.
  const [fromX, toX] = pixelsCovering(left, right, 1 / scaleX, image.width);
  const [fromY, toY] = pixelsCovering(top, bottom, 1 / scaleY, image.height);
  const columns = spans(fromX, toX, scaleX, left);
  const rows = spans(fromY, toY, scaleY, top);
  // Per canvas pixel: weighted sums of R, G, B, and of the weights.
  // Path mode shows radiance times 2^exposure (quantize.ts): clamped after that scale, as shown.
  const scale = quantization.integrator === 'path' ? 2 ** quantization.exposure : 1;
  const sums = new Float64Array(width * height * 4);
  const add = (row: number, column: number, weight: number, r: number, g: number, b: number) => {
    if (weight <= 0 || row < 0 || column < 0 || row >= height || column >= width) return;
    const at = (row * width + column) * 4;
    sums[at] += weight * r;
    sums[at + 1] += weight * g;
    sums[at + 2] += weight * b;
    sums[at + 3] += weight;
  };
  for (let y = fromY; y < toY; y++) {
    const row = rows.first[y - fromY];
    const rowShare = rows.share[y - fromY];
    for (let x = fromX; x < toX; x++) {
      const pixel = y * image.width + x;
      if (rendered && !rendered[pixel]) continue;
      const r = Math.min(1, Math.max(0, image.rgb[pixel * 3] * scale));
      const g = Math.min(1, Math.max(0, image.rgb[pixel * 3 + 1] * scale));
      const b = Math.min(1, Math.max(0, image.rgb[pixel * 3 + 2] * scale));
      const column = columns.first[x - fromX];
      const columnShare = columns.share[x - fromX];
      add(row, column, rowShare * columnShare, r, g, b);
      add(row, column + 1, rowShare * (columns.span - columnShare), r, g, b);
      add(row + 1, column, (rows.span - rowShare) * columnShare, r, g, b);
      add(row + 1, column + 1, (rows.span - rowShare) * (columns.span - columnShare), r, g, b);
    }
  }
  const rgb = new Float32Array(width * height * 3);
  for (let i = 0; i < width * height; i++) {
    const weight = sums[i * 4 + 3];
    if (weight > 0) for (let c = 0; c < 3; c++) rgb[i * 3 + c] = sums[i * 4 + c] / weight;
  }
  const rgba = toRgba8(rgb, width, height, { ...quantization, exposure: 0 });
  return {
    x: left,
    y: top,
    pixels: new ImageData(rgba as Uint8ClampedArray<ArrayBuffer>, width, height),
    part: { x: touchedLeft - left, y: touchedTop - top, width: right - touchedLeft, height: bottom - touchedTop },
  };
}
