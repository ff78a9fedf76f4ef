import { isRecord } from './is-record.ts';

/**
 * Whether two pieces of plain data (what JSON holds: numbers, strings, booleans, null,
 * lists and plain objects) hold the same values, however deep. Numbers compare as `===`
 * does (so NaN is never the same; the scene schema refuses it anyway).
 */
export function sameValue(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (Array.isArray(a)) return Array.isArray(b) && a.length === b.length && a.every((item, index) => sameValue(item, b[index]));
  if (isRecord(a) && isRecord(b)) {
    const keys = Object.keys(a);
    return keys.length === Object.keys(b).length && keys.every((key) => Object.hasOwn(b, key) && sameValue(a[key], b[key]));
  }
  return false;
}
