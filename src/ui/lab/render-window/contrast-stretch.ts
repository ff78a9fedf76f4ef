/**
 * "Stretch contrast" for the render window: a dark, smooth gradient climbs only a few of the
 * 256 levels of an 8-bit image, so its bands, one level apart, are hard to see on screen.
 * It works on the values on screen (for `encoding: 'linear'`, the bytes that show each stored
 * level: quantize.ts). A linear stretch maps the image's own darkest level to
 * 0 and its brightest to 255 (a full-scale contrast stretch, e.g. Gonzalez & Woods, Digital
 * Image Processing, §3.2): every level stays a level of its own and keeps its order, so the
 * bands and the dither pattern are kept, only further apart in brightness.
 */

/** The darkest and brightest channel value (red, green or blue) of an RGBA image. */
export interface LevelRange {
  low: number;
  high: number;
}

export function levelRange(rgba: ArrayLike<number>): LevelRange {
  let low = 255;
  let high = 0;
  for (let i = 0; i < rgba.length; i += 4) {
    for (let channel = i; channel < i + 3; channel++) {
      const value = rgba[channel]!;
      if (value < low) low = value;
      if (value > high) high = value;
    }
  }
  return low > high ? { low: 0, high: 255 } : { low, high };
}

/**
 * The image with each channel value v mapped to round(255 · (v − low) / (high − low)),
 * alpha kept. An image of one level (high = low) has nothing to stretch and is copied.
 */
export function stretchContrast(rgba: ArrayLike<number>, { low, high }: LevelRange = levelRange(rgba)): Uint8ClampedArray {
  const out = Uint8ClampedArray.from(rgba);
  if (high <= low) return out;
  const table = new Uint8ClampedArray(256);
  for (let v = 0; v < 256; v++) table[v] = Math.round((255 * (v - low)) / (high - low));
  for (let i = 0; i < out.length; i += 4) {
    out[i] = table[out[i]!]!;
    out[i + 1] = table[out[i + 1]!]!;
    out[i + 2] = table[out[i + 2]!]!;
  }
  return out;
}
