/**
 * What a unit shape's test is asked and what it answers, kept in a typed array instead of
 * passed as an argument and returned: `span[REACH]` is the far end of the interval (0, reach)
 * the test searches, and a test that finds the shape writes the nearest t there into
 * `span[FOUND]`. A Float64Array holds its numbers unboxed: docs/performance.md, "Numbers
 * passed to calls".
 */
export type UnitSpan = Float64Array;

export const REACH = 0;
export const FOUND = 1;

export function unitSpan(): UnitSpan {
  return new Float64Array(2);
}
