/**
 * 8-bit quantization of the linear image: round(clamp(c)·255) per channel, no gamma
 * (matching the Virtual Ray Tracer), alpha 255.
 *
 * Optional ordered dithering adds a 4×4 Bayer threshold of ±½ step before rounding, so
 * smooth dark gradients turn into fine patterns instead of visible bands (Bayer 1973).
 */
const BAYER_4X4 = [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5];

export function toRgba8(rgb: Float32Array, width: number, height: number, dithering: boolean): Uint8ClampedArray {
  const rgba = new Uint8ClampedArray(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const pixel = y * width + x;
      // Threshold in (−0.5, 0.5) of one 8-bit step; 0 when dithering is off (exact rounding).
      const offset = dithering ? (BAYER_4X4[(y & 3) * 4 + (x & 3)] + 0.5) / 16 - 0.5 : 0;
      for (let c = 0; c < 3; c++) {
        const value = Math.min(1, Math.max(0, rgb[pixel * 3 + c]));
        rgba[pixel * 4 + c] = Math.round(value * 255 + offset);
      }
      rgba[pixel * 4 + 3] = 255;
    }
  }
  return rgba;
}
