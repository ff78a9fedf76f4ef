import { describe, expect, test } from 'vitest';
import { formatNumber, parseTypedNumber, readTypedNumber, typedNumberMessage, type NumberRange } from '../../../src/ui/controls/number-input.ts';
import { inDutch } from '../../support/page-locale.ts';

const spot: NumberRange = { min: 1, max: 170 };
const coefficient: NumberRange = { min: 0, max: 1 };
const percent: NumberRange = { min: 0, max: 1, percent: true };
const samples: NumberRange = { min: 1, max: 10, whole: true };

describe('parseTypedNumber', () => {
  test('reads a decimal point and a decimal comma alike', () => {
    expect(parseTypedNumber('0.5', coefficient)).toEqual({ kind: 'ok', value: 0.5 });
    expect(parseTypedNumber('0,5', coefficient)).toEqual({ kind: 'ok', value: 0.5 });
    expect(parseTypedNumber(' ,25 ', coefficient)).toEqual({ kind: 'ok', value: 0.25 });
  });

  test('takes the last of "." and "," as the decimal point, the other as thousands', () => {
    const wide = { min: 0, max: 10_000 };
    expect(parseTypedNumber('1.000,5', wide)).toEqual({ kind: 'ok', value: 1000.5 });
    expect(parseTypedNumber('1,000.5', wide)).toEqual({ kind: 'ok', value: 1000.5 });
    // A lone comma is decimal, as on a Dutch keyboard.
    expect(parseTypedNumber('1,000', wide)).toEqual({ kind: 'ok', value: 1 });
    expect(parseTypedNumber('1.2.3', wide)).toEqual({ kind: 'invalid' });
  });

  test('reads a typographic minus, a plus sign and exponents', () => {
    const coordinate = { min: -10_000, max: 10_000 };
    expect(parseTypedNumber('−2.5', coordinate)).toEqual({ kind: 'ok', value: -2.5 });
    expect(parseTypedNumber('+3', coordinate)).toEqual({ kind: 'ok', value: 3 });
    expect(parseTypedNumber('1e3', coordinate)).toEqual({ kind: 'ok', value: 1000 });
  });

  test('percent: "50%" is a half in any field, a bare "50" only in a percent field', () => {
    expect(parseTypedNumber('50%', coefficient)).toEqual({ kind: 'ok', value: 0.5 });
    expect(parseTypedNumber('50 %', percent)).toEqual({ kind: 'ok', value: 0.5 });
    expect(parseTypedNumber('50', percent)).toEqual({ kind: 'ok', value: 0.5 });
    expect(parseTypedNumber('12,5', percent)).toEqual({ kind: 'ok', value: 0.125 });
    expect(parseTypedNumber('50', coefficient)).toEqual({ kind: 'clamped', value: 1 });
  });

  test("accepts the field's own unit after the number", () => {
    expect(parseTypedNumber('45°', spot, '°')).toEqual({ kind: 'ok', value: 45 });
    expect(parseTypedNumber('2 m', { min: 0, max: 10 }, 'm')).toEqual({ kind: 'ok', value: 2 });
    expect(parseTypedNumber('45m', spot, '°')).toEqual({ kind: 'invalid' });
  });

  test('clamps out-of-range numbers to the nearer end', () => {
    expect(parseTypedNumber('400', spot)).toEqual({ kind: 'clamped', value: 170 });
    expect(parseTypedNumber('0', spot)).toEqual({ kind: 'clamped', value: 1 });
    expect(parseTypedNumber('-5', spot)).toEqual({ kind: 'clamped', value: 1 });
    expect(parseTypedNumber('1e999', spot)).toEqual({ kind: 'clamped', value: 170 });
    expect(parseTypedNumber('170', spot)).toEqual({ kind: 'ok', value: 170 });
  });

  test('rounds fractions in a whole-number field, after clamping', () => {
    expect(parseTypedNumber('2.5', samples)).toEqual({ kind: 'rounded', value: 3 });
    expect(parseTypedNumber('2,4', samples)).toEqual({ kind: 'rounded', value: 2 });
    expect(parseTypedNumber('10.5', samples)).toEqual({ kind: 'clamped', value: 10 });
    expect(parseTypedNumber('4', samples)).toEqual({ kind: 'ok', value: 4 });
  });

  test('refuses text that is not a number', () => {
    for (const text of ['abc', '', '  ', '-', '.', '1..2', '1,2,3', '12abc', '0x10', '%', 'Infinity', 'NaN']) {
      expect(parseTypedNumber(text, spot), text).toEqual({ kind: 'invalid' });
    }
  });
});

describe('typedNumberMessage', () => {
  test('says what happened, in the units the field shows', () => {
    expect(typedNumberMessage({ kind: 'ok', value: 4 }, spot)).toBeUndefined();
    expect(typedNumberMessage({ kind: 'clamped', value: 170 }, spot)).toBe('Clamped to 1–170');
    expect(typedNumberMessage({ kind: 'clamped', value: 1 }, percent)).toBe('Clamped to 0–100 %');
    expect(typedNumberMessage({ kind: 'clamped', value: 4 }, { min: 1, max: 4 })).toBe('Clamped to 1–4');
    expect(typedNumberMessage({ kind: 'rounded', value: 3 }, samples)).toBe('Rounded to 3 (whole numbers only)');
  });

  test('tells what to type when the text is not a number', () => {
    expect(typedNumberMessage({ kind: 'invalid' }, spot)).toBe('Type a number between 1 and 170');
    expect(typedNumberMessage({ kind: 'invalid' }, samples)).toBe('Type a whole number between 1 and 10');
    expect(typedNumberMessage({ kind: 'invalid' }, percent)).toBe('Type a number between 0 and 100');
  });

  test('readTypedNumber gives the value to commit and the note together', () => {
    expect(readTypedNumber('400', spot)).toEqual({ value: 170, note: 'Clamped to 1–170' });
    expect(readTypedNumber('abc', spot)).toEqual({ value: undefined, note: 'Type a number between 1 and 170' });
    expect(readTypedNumber('0,5', coefficient)).toEqual({ value: 0.5, note: undefined });
  });

  test('a clamped number is told the reason for the limit when the range has one', () => {
    const imageSide = { min: 1, max: 4096, whole: true, why: 'the tracer renders at most 4096 pixels per side' };
    expect(readTypedNumber('5000', imageSide, 'px')).toEqual({ value: 4096, note: 'Clamped to 1–4096: the tracer renders at most 4096 pixels per side' });
    expect(readTypedNumber('4000', imageSide, 'px')).toEqual({ value: 4000, note: undefined });
  });
});

describe('formatNumber', () => {
  test('shows as many decimals as the step', () => {
    expect(formatNumber(0.5, 0.01)).toBe('0.50');
    expect(formatNumber(40, 1)).toBe('40');
    expect(formatNumber(1.5, 0.5)).toBe('1.5');
    expect(formatNumber(0, 0.1)).toBe('0.0');
  });

  test('shows a finer value (typed, or set by the gizmo) with up to 4 decimals', () => {
    expect(formatNumber(0.123, 0.01)).toBe('0.123');
    expect(formatNumber(1 / 3, 0.01)).toBe('0.3333');
    expect(formatNumber(32.5, 1)).toBe('32.5');
  });

  test('shows a percent field in percent, without float noise', () => {
    expect(formatNumber(0.07, 0.01, true)).toBe('7');
    expect(formatNumber(0.5, 0.001, true)).toBe('50.0');
    expect(formatNumber(0.125, 0.01, true)).toBe('12.5');
  });
});

describe('in Dutch', () => {
  inDutch();

  test('a field shows a decimal comma and no thousands separator, and reads its own text back', () => {
    expect(formatNumber(0.5, 0.01)).toBe('0,50');
    expect(formatNumber(1234.5, 0.1)).toBe('1234,5');
    expect(formatNumber(0.12345, 0.01)).toBe('0,1235');
    expect(formatNumber(0.25, 0.01, true)).toBe('25');
    for (const value of [0.5, 1234.5, -2.25, 0.1235]) {
      expect(parseTypedNumber(formatNumber(value, 0.01), { min: -10_000, max: 10_000 })).toEqual({ kind: 'ok', value });
    }
  });

  test('takes "0,5" and "0.5" alike, as typed on any keyboard', () => {
    expect(readTypedNumber('0,5', coefficient)).toEqual({ value: 0.5, note: undefined });
    expect(readTypedNumber('0.5', coefficient)).toEqual({ value: 0.5, note: undefined });
  });

  test('writes the ranges of its notes the Dutch way, wholly in Dutch', () => {
    expect(typedNumberMessage({ kind: 'invalid' }, { min: 0.001, max: 1000 })).toBe('Typ een getal van 0,001 tot en met 1000');
    expect(typedNumberMessage({ kind: 'clamped', value: 1.5 }, { min: 1, max: 2.5 })).toBe('Aangepast tot binnen 1–2,5');
  });
});
