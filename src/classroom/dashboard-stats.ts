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

/**
 * Where a time axis for these rows should end: at the longest time that is not an outlier
 * by Tukey's rule (above Q3 + 1.5 × IQR; Tukey, Exploratory Data Analysis, 1977), so one
 * learner who left the tab open for 20 minutes does not squeeze everyone else into the
 * left edge. Longer times are drawn at the end of the axis, marked as beyond it.
 */
export function axisEnd(rows: readonly { times: readonly number[]; stats: FiveNumbers | null }[]): number {
  const ends = rows.map((row) => {
    if (!row.stats) return 0;
    const fence = row.stats.q3 + 1.5 * (row.stats.q3 - row.stats.q1);
    return Math.max(0, ...row.times.filter((time) => time <= fence));
  });
  return Math.max(0, ...ends);
}
