/**
 * x^n for the Phong highlight (R·V)^n, x in [0, 1].
 *
 * The highlight is raised once per shadow sample that reaches the light: tens of millions
 * of times in a render, where Math.pow is a general-purpose pow (docs/performance.md,
 * "Math.pow"). Shininess is almost always a whole number, and for a whole n,
 * exponentiation by squaring (Knuth, TAOCP vol. 2, §4.6.3) needs at most 2·log2(n)
 * multiplications. Its result can differ from Math.pow's in the last bits
 * (relative error below 1e-12 up to the largest shininess the scene format allows), far
 * below what an 8-bit or even a float32 pixel can hold. A fractional n keeps Math.pow.
 *
 * The image and every ray tree both come through this one function, so a pixel's tree
 * still has exactly the image's colour.
 */
export function phongPower(x: number, n: number): number {
  // n | 0 is n itself only for a whole n in the 32-bit range (shininess is at most 10 000).
  if ((n | 0) !== n || n < 0) return Math.pow(x, n);
  let result = 1;
  let base = x;
  for (let e = n; e !== 0; e >>= 1) {
    if (e & 1) result *= base;
    base *= base;
  }
  return result;
}
