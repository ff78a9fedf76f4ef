/**
 * How much a given difference of one byte is amplified in the difference picture: a
 * difference of a few steps out of 255 becomes plain to see on black.
 */
export const DIFFERENCE_GAIN = 8;

/** The least brightness of a pixel that differs at all: a difference of 1 step must not vanish into the black. */
const LEAST_SEEN = 64;

/**
 * |mine − reference| per channel of two RGBA pictures of the same size, amplified by
 * DIFFERENCE_GAIN (a differing channel at least LEAST_SEEN), opaque; and how many pixels
 * differ in any channel. Equal pictures give a black picture and 0.
 */
export function pictureDifference(mine: Uint8ClampedArray, reference: Uint8ClampedArray): { rgba: Uint8ClampedArray<ArrayBuffer>; differing: number } {
  const rgba = new Uint8ClampedArray(mine.length);
  let differing = 0;
  for (let i = 0; i < mine.length; i += 4) {
    let differs = false;
    for (let c = 0; c < 3; c++) {
      const step = Math.abs(mine[i + c]! - reference[i + c]!);
      if (step > 0) differs = true;
      rgba[i + c] = step === 0 ? 0 : Math.max(LEAST_SEEN, step * DIFFERENCE_GAIN);
    }
    rgba[i + 3] = 255;
    if (differs) differing++;
  }
  return { rgba, differing };
}
