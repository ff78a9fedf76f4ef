/**
 * What a unit shape's test is asked and what it answers, kept in a typed array instead of
 * passed as an argument and returned: `span[REACH]` is the far end of the interval (0, reach)
 * the test searches, and a test that finds the shape writes the nearest t there into
 * `span[FOUND]`. V8 allocates a heap number for every fractional number passed to, or
 * returned from, a call it does not inline: a third of the reference image made 127 MB of
 * garbage with the shapes' reach and t passed and returned, 75 MB without (a sampling heap
 * profile, collected objects included; docs/benchmarks.md, ninth round). A Float64Array
 * holds its numbers unboxed.
 */
export type UnitSpan = Float64Array;

export const REACH = 0;
export const FOUND = 1;

export function unitSpan(): UnitSpan {
  return new Float64Array(2);
}
