import type { RenderSettings } from '../scene/scene.ts';
import { linearToSrgb, srgbToLinear } from './srgb.ts';

/**
 * 8-bit quantization of the tracer's image: its colours c (0..1 per channel, clamped) become
 * the RGBA bytes of the canvas and of a saved PNG, alpha 255. A screen shows a byte b as the
 * light srgbToLinear(b / 255) (srgb.ts), so each setting of `encoding` says what the bytes
 * mean and makes them show it:
 *
 * - 'none' (the default, matching the Virtual Ray Tracer): b = round(255·c), no gamma. The
 *   screen takes c as its own value, so the light shown is srgbToLinear(c), not c.
 * - 'linear': the light c is stored in 8 bits as the level q = round(255·c), every step the same
 *   light (1/255 of white). The byte shows that level's light: b = round(255·linearToSrgb(q/255)).
 *   Near black a level is several bytes apart from the next (q = 1 → b = 13, q = 2 → 22);
 *   from q = 76 (30 % of white) on, where the encoding is flatter, some neighbouring levels
 *   share a byte: 183 of the 256 levels can be told apart on an 8-bit screen.
 * - 'srgb': the light is sRGB-encoded before it is rounded, b = round(255·linearToSrgb(c)), as
 *   image files are (Poynton, "Digital Video and HD", the chapter on gamma): the screen's
 *   decoding gives c back, and the 256 levels, evenly spread in encoded value, lie close
 *   together in dark light.
 *
 * Optional ordered dithering adds a 4×4 Bayer threshold of ±½ step before the rounding that
 * stores the level (Bayer 1973), so a smooth gradient turns into a fine pattern of the two
 * levels around each value instead of visible bands.
 */
const BAYER_4X4 = [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5];

/**
 * What decides the image's 8-bit values: the scene's settings of those names. In path mode
 * the picture is radiance, shown sRGB-encoded after multiplying by 2^exposure, whatever
 * `encoding` says (path-tracing spec §2: the linear values are what a `.pfm` keeps).
 */
export type Quantization = Pick<RenderSettings, 'dithering' | 'encoding' | 'integrator' | 'exposure'>;

/** The defaults' quantization: c·255 with no gamma and no dithering, a Whitted picture. */
export const PLAIN_QUANTIZATION: Quantization = { dithering: false, encoding: 'none', integrator: 'whitted', exposure: 0 };

/** The threshold in (−0.5, 0.5) of one 8-bit step that Bayer entry k adds; none (0) for k = 16, no dithering. */
const threshold = (k: number) => (k === 16 ? 0 : (k + 0.5) / 16 - 0.5);

/** The byte that shows each linear level q (0..255) as its light, for `encoding: 'linear'`. */
const LINEAR_LEVEL_BYTES = Uint8ClampedArray.from({ length: 256 }, (_, q) => Math.round(255 * linearToSrgb(q / 255)));

/**
 * For `encoding: 'srgb'`, per threshold k (0..15, 16 for none): the light at which each byte b
 * starts, S((b − 0.5 − threshold)/255) (b ≥ 1; byte 0 starts at −∞), so that
 * round(255·E(c) + threshold) is the last byte whose start is ≤ c. Looked up rather than
 * computed: a power per channel made an sRGB image 13 times slower to quantize than a linear
 * one (2.7 s for 2048 × 1536 in Node).
 */
const SRGB_BYTE_STARTS = Array.from({ length: 17 }, (_, k) =>
  Float64Array.from({ length: 256 }, (_, b) => (b === 0 ? -Infinity : srgbToLinear((b - 0.5 - threshold(k)) / 255))),
);

/**
 * The light 0..1 in this many equal bins, each knowing the byte at its start: a light's byte is
 * then at most a step or two further. A power of two, so light · SRGB_BINS is exact.
 */
const SRGB_BINS = 4096;

/** Per threshold k, the byte of each bin's start i / SRGB_BINS (and of 1, the last): one walk up the bytes. */
const SRGB_BIN_BYTES = SRGB_BYTE_STARTS.map((starts) => {
  const bytes = new Uint8Array(SRGB_BINS + 1);
  let byte = 0;
  for (let i = 0; i <= SRGB_BINS; i++) {
    while (byte < 255 && starts[byte + 1]! <= i / SRGB_BINS) byte++;
    bytes[i] = byte;
  }
  return bytes;
});

/** The last byte whose light starts at or below `light` (0..1), for threshold k. */
function srgbByte(k: number, light: number): number {
  const starts = SRGB_BYTE_STARTS[k]!;
  let byte = SRGB_BIN_BYTES[k]![Math.floor(light * SRGB_BINS)]!;
  while (byte < 255 && starts[byte + 1]! <= light) byte++;
  return byte;
}

export function toRgba8(rgb: Float32Array, width: number, height: number, quantization: Quantization): Uint8ClampedArray {
  const { dithering } = quantization;
  const path = quantization.integrator === 'path';
  const encoding = path ? 'srgb' : quantization.encoding;
  const scale = path ? 2 ** quantization.exposure : 1;
  const rgba = new Uint8ClampedArray(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const pixel = y * width + x;
      const k = dithering ? BAYER_4X4[(y & 3) * 4 + (x & 3)] : 16;
      const offset = threshold(k);
      for (let c = 0; c < 3; c++) {
        const value = Math.min(1, Math.max(0, rgb[pixel * 3 + c] * scale));
        rgba[pixel * 4 + c] =
          encoding === 'none'
            ? Math.round(value * 255 + offset)
            : encoding === 'linear'
              ? LINEAR_LEVEL_BYTES[Math.round(value * 255 + offset)]
              : srgbByte(k, value);
      }
      rgba[pixel * 4 + 3] = 255;
    }
  }
  return rgba;
}

/**
 * The RGB bytes toRgba8 stores for pixel (x, y) of an image when its colour is `color` (the
 * ray debugger shows them): that pixel's place in the 4×4 Bayer pattern, in an image just
 * large enough to hold it, so it is exactly the image's quantization.
 */
export function pixelBytes(color: readonly number[], x: number, y: number, quantization: Quantization): [number, number, number] {
  const width = (x & 3) + 1;
  const height = (y & 3) + 1;
  const rgb = new Float32Array(width * height * 3);
  const at = ((y & 3) * width + (x & 3)) * 3;
  rgb.set(color.slice(0, 3), at);
  const rgba = toRgba8(rgb, width, height, quantization);
  return [rgba[(at / 3) * 4], rgba[(at / 3) * 4 + 1], rgba[(at / 3) * 4 + 2]];
}
