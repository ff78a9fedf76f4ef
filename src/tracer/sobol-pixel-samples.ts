/**
 * Stratified points in a pixel's square for path mode: the first two dimensions of the Sobol
 * sequence, Owen-scrambled per pixel with Burley's hash ("Practical Hash-based Owen
 * Scrambling", JCGT 9(4), 2020). This is Cycles' "Sobol-Burley" pattern (Blender 3.4's other
 * pattern, its default, progressive multi-jittered (0, 2) sequences, stratifies a pixel the
 * same way) and what pbrt-v4's Sobol samplers draw for a pixel sample (pbrt-v4 §8.7).
 *
 * Why: the first 2^m points form a (0, m, 2)-net, one point in each of the 2^m boxes of area
 * 2^-m of every shape (1 × 2^-m, …, 2^-m × 1). A pixel an edge crosses is then measured far
 * more evenly than by independent random points (pbrt-v4 §8.5). The stratification holds for
 * every power-of-two prefix, so it needs no total count: the render window's progressive
 * passes and `rt trace --paths K` draw the same points as a one-pass render.
 *
 * Why it stays unbiased: the scramble adds a uniformly random seed to the reversed bits and
 * then applies bijections, so over the random seeds each point is uniform over the 2^32 × 2^32
 * grid of the square; only the points of one pixel are correlated (they avoid each other).
 */

/** The second Sobol dimension's direction numbers (primitive polynomial x + 1: Pascal's triangle mod 2). */
const SECOND_DIMENSION = new Uint32Array(32);
SECOND_DIMENSION[0] = 0x80000000;
for (let bit = 1; bit < 32; bit++) SECOND_DIMENSION[bit] = SECOND_DIMENSION[bit - 1]! ^ (SECOND_DIMENSION[bit - 1]! >>> 1);

/** 2^-32: a 32-bit integer times it is a number in [0, 1), to the bit. */
const TWO_TO_MINUS_32 = 1 / 4294967296;

/** The 32 bits of v in reverse order, as an unsigned integer. */
export function reverseBits32(v: number): number {
  v = ((v >>> 1) & 0x55555555) | ((v & 0x55555555) << 1);
  v = ((v >>> 2) & 0x33333333) | ((v & 0x33333333) << 2);
  v = ((v >>> 4) & 0x0f0f0f0f) | ((v & 0x0f0f0f0f) << 4);
  v = ((v >>> 8) & 0x00ff00ff) | ((v & 0x00ff00ff) << 8);
  return ((v >>> 16) | (v << 16)) >>> 0;
}

/**
 * Owen scrambling of a 32-bit fraction by hashing (Burley 2020, after Laine and Karras): on the
 * reversed bits, each step changes a bit only by the bits below it, so in the fraction each
 * digit is flipped by a function of the digits above it, which is Owen's nested scrambling.
 */
export function owenScramble(v: number, seed: number): number {
  let x = reverseBits32(v);
  x = (x + seed) | 0;
  x ^= Math.imul(x, 0x6c50b47c);
  x ^= Math.imul(x, 0xb82f1e52);
  x ^= Math.imul(x, 0xc7afe638);
  x ^= Math.imul(x, 0x8d22f6e6);
  return reverseBits32(x);
}

/** The index-th point of the unscrambled two-dimensional Sobol sequence, as two 32-bit fractions. */
export function sobolPoint(index: number, out: [number, number]): [number, number] {
  let y = 0;
  for (let bit = 0, rest = index >>> 0; rest !== 0; bit++, rest >>>= 1) if (rest & 1) y ^= SECOND_DIMENSION[bit]!;
  out[0] = reverseBits32(index);
  out[1] = y >>> 0;
  return out;
}

const bits: [number, number] = [0, 0];

/**
 * The index-th point of a pixel's scrambled sequence, in [0, 1)², written to `out`. `scrambleU`
 * and `scrambleV` are the pixel's two random seeds (independent 32-bit hashes).
 */
export function pixelSamplePoint(index: number, scrambleU: number, scrambleV: number, out: [number, number]): [number, number] {
  sobolPoint(index, bits);
  out[0] = owenScramble(bits[0], scrambleU) * TWO_TO_MINUS_32;
  out[1] = owenScramble(bits[1], scrambleV) * TWO_TO_MINUS_32;
  return out;
}
