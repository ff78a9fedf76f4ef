import { type Quantization, toRgba8 } from '../tracer/quantize.ts';
import type { RenderImage } from './render-job.ts';

/** The ordered dithering pattern repeats every this many rows (quantize.ts's 4×4 Bayer matrix). */
export const DITHER_PERIOD = 4;

/**
 * Rows `fromRow` to `toRow` (exclusive; default the whole image) of a rendered image (linear
 * RGB floats) as canvas pixels: quantized by toRgba8 exactly like the `rt render` PNG, with the
 * scene's dithering and encoding settings, so what the student sees on screen is what the
 * saved file and the command line produce.
 *
 * A band must start at a multiple of DITHER_PERIOD: toRgba8 picks the dither threshold by the
 * row within what it is given, so only then do the bands match the whole image's pattern.
 */
export function renderImageData(image: RenderImage, quantization: Quantization, fromRow = 0, toRow = image.height): ImageData {
  if (fromRow % DITHER_PERIOD !== 0 || fromRow < 0 || toRow > image.height || toRow <= fromRow) {
    throw new RangeError(`rows ${fromRow}..${toRow} are not a band of ${image.height} rows starting at a multiple of ${DITHER_PERIOD}`);
  }
  const rows = toRow - fromRow;
  const rgb = image.rgb.subarray(fromRow * image.width * 3, toRow * image.width * 3);
  const rgba = toRgba8(rgb, image.width, rows, quantization);
  // toRgba8 allocates its array itself, so it owns a plain ArrayBuffer (never shared memory),
  // which is what ImageData takes; wrapping it saves a copy.
  return new ImageData(rgba as Uint8ClampedArray<ArrayBuffer>, image.width, rows);
}
