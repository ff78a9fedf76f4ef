/**
 * The sRGB transfer function (IEC 61966-2-1:1999; Poynton, "Digital Video and HD", the chapter
 * on gamma): how an image file's values relate to light. A screen shows an 8-bit value v as the
 * light srgbToLinear(v / 255) (as a fraction of its white); a file that is to show light L
 * stores linearToSrgb(L) · 255.
 *
 * The curve is a straight line near black (slope 12.92) joined to a power 1/2.4 with an
 * offset; overall it is close to L^(1/2.2). It is steep for dark light, so an 8-bit file spends
 * many of its 256 values on dark tones, where the eye tells small relative steps apart.
 */

/** Light (0..1, a fraction of white) → its sRGB-encoded value (0..1). */
export function linearToSrgb(light: number): number {
  return light <= 0.0031308 ? 12.92 * light : 1.055 * Math.pow(light, 1 / 2.4) - 0.055;
}

/** An sRGB-encoded value (0..1) → the light it stands for (0..1). */
export function srgbToLinear(value: number): number {
  return value <= 0.04045 ? value / 12.92 : Math.pow((value + 0.055) / 1.055, 2.4);
}
