/**
 * Pearson's χ² test of counts in cells of equal probability, for the samplers' tests: a
 * correct sampler gives χ² near its degrees of freedom (cells − 1), a biased one far above.
 */

/** Σ (observed − expected)² / expected, with `total / counts.length` expected in each cell. */
export function chiSquare(counts: ArrayLike<number>): number {
  let total = 0;
  for (let i = 0; i < counts.length; i++) total += counts[i];
  const expected = total / counts.length;
  let sum = 0;
  for (let i = 0; i < counts.length; i++) sum += (counts[i] - expected) ** 2 / expected;
  return sum;
}

/**
 * The χ² value a correct sampler exceeds with probability 0.001 for `dof` degrees of
 * freedom, by Wilson and Hilferty's cube-root approximation (1931), within 1 % for dof ≥ 30:
 * dof·(1 − 2/(9·dof) + z·√(2/(9·dof)))³ with z = 3.09, the normal's 0.999 quantile.
 */
export function chiSquareLimit(dof: number): number {
  const a = 2 / (9 * dof);
  return dof * (1 - a + 3.09 * Math.sqrt(a)) ** 3;
}
