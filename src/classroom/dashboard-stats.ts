/**
 * Summary statistics of a class's times: the five numbers of a box plot.
 *
 * Quantiles interpolate linearly between the sorted values (Hyndman & Fan type 7, the
 * default of R, NumPy and spreadsheet QUARTILE.INC), so a teacher who checks a median in a
 * spreadsheet finds the same number.
 */
export interface FiveNumbers {
  count: number;
  min: number;
  q1: number;
  median: number;
  q3: number;
  max: number;
}

/** The value below which a fraction `p` (0..1) of the sorted `values` lie; NaN for none. */
export function quantile(sorted: readonly number[], p: number): number {
  if (sorted.length === 0) return Number.NaN;
  const position = (sorted.length - 1) * p;
  const below = Math.floor(position);
  const above = Math.min(below + 1, sorted.length - 1);
  return sorted[below] + (sorted[above] - sorted[below]) * (position - below);
}

/** Minimum, quartiles, median and maximum of `values` (in any order); null for no values. */
export function fiveNumbers(values: readonly number[]): FiveNumbers | null {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  return {
    count: sorted.length,
    min: sorted[0],
    q1: quantile(sorted, 0.25),
    median: quantile(sorted, 0.5),
    q3: quantile(sorted, 0.75),
    max: sorted[sorted.length - 1],
  };
}
