import { expect, test } from 'vitest';
import { sameValue } from '../../src/util/same-value.ts';

test('plain data with the same values is the same, however deep', () => {
  expect(sameValue([1, 2, 3], [1, 2, 3])).toBe(true);
  expect(sameValue({ a: [0, { b: 'x' }], c: null }, { c: null, a: [0, { b: 'x' }] })).toBe(true);
  expect(sameValue(0.5, 0.5)).toBe(true);
});

test('a different value, length or key anywhere is a difference', () => {
  expect(sameValue([1, 2, 3], [1, 2, 4])).toBe(false);
  expect(sameValue([1, 2], [1, 2, 3])).toBe(false);
  expect(sameValue({ a: 1 }, { a: 1, b: undefined })).toBe(false);
  expect(sameValue({ a: 1, b: undefined }, { a: 1, c: undefined })).toBe(false);
  expect(sameValue({ a: { b: 1 } }, { a: { b: 2 } })).toBe(false);
  expect(sameValue([1], { 0: 1 })).toBe(false);
  expect(sameValue(null, {})).toBe(false);
  expect(sameValue(Number.NaN, Number.NaN)).toBe(false);
});
