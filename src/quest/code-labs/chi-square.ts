/**
 * Pearson's χ² test of counts against expected counts, and its p-value: the chance that a
 * sample from the expected density lies at least this far from it. The p-value is the
 * regularized upper incomplete gamma function Q(k/2, χ²/2) for k degrees of freedom,
 * computed as in Press et al., "Numerical Recipes", 3rd ed., §6.2 (a series below a + 1, a
 * continued fraction above). Nori's sample-warping tests grade a random function the same way.
 */

/** ln Γ(x) for x > 0 (Lanczos, as Numerical Recipes §6.1 `gammln`). */
function lnGamma(x: number): number {
  const coefficients = [76.18009172947146, -86.50532032941678, 24.01409824083091, -1.231739572450155, 0.1208650973866179e-2, -0.5395239384953e-5];
  let y = x;
  const tmp = x + 5.5 - (x + 0.5) * Math.log(x + 5.5);
  let series = 1.000000000190015;
  for (const c of coefficients) series += c / ++y;
  return -tmp + Math.log((2.5066282746310007 * series) / x);
}

/** Q(a, x) = Γ(a, x) / Γ(a), the regularized upper incomplete gamma function. */
export function upperGamma(a: number, x: number): number {
  if (x <= 0) return 1;
  const front = Math.exp(-x + a * Math.log(x) - lnGamma(a));
  if (x < a + 1) {
    // P(a, x) by its series; Q = 1 − P.
    let term = 1 / a;
    let sum = term;
    for (let n = 1; n < 1000 && Math.abs(term) > Math.abs(sum) * 1e-15; n++) {
      term *= x / (a + n);
      sum += term;
    }
    return Math.max(0, 1 - sum * front);
  }
  // Q(a, x) by Lentz's continued fraction.
  const tiny = 1e-300;
  let b = x + 1 - a;
  let c = 1 / tiny;
  let d = 1 / b;
  let h = d;
  for (let i = 1; i < 1000; i++) {
    const an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (Math.abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (Math.abs(c) < tiny) c = tiny;
    d = 1 / d;
    const step = d * c;
    h *= step;
    if (Math.abs(step - 1) < 1e-15) break;
  }
  return front * h;
}

export interface ChiSquare {
  value: number;
  degrees: number;
  p: number;
}

/** χ² of observed against expected counts (bins with nothing expected are left out), its degrees of freedom and p-value. */
export function chiSquare(observed: readonly number[], expected: readonly number[]): ChiSquare {
  let value = 0;
  let bins = 0;
  observed.forEach((count, bin) => {
    const wanted = expected[bin] ?? 0;
    if (wanted <= 0) return;
    value += (count - wanted) ** 2 / wanted;
    bins++;
  });
  const degrees = Math.max(1, bins - 1);
  return { value, degrees, p: upperGamma(degrees / 2, value / 2) };
}
