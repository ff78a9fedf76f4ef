import { localNumbers, numberList } from '../../../i18n/number-format.ts';

/** One formatter per number of significant digits the labs show (2 for p-values, 3 for χ², 6 for answers). */
const formats = new Map<number, { format(value: number): string }>();

/**
 * A number of a code lab's report to `digits` significant digits, as the reader's language
 * writes it: "0.000013" in English, "0,000013" in Dutch, without thousands separators (a
 * learner compares it with what their code printed). NaN and ±Infinity stay as JavaScript
 * writes them: they are what the learner's function returned.
 */
export function labNumber(value: number, digits = 6): string {
  if (!Number.isFinite(value)) return String(value);
  let format = formats.get(digits);
  if (!format) formats.set(digits, (format = localNumbers({ maximumSignificantDigits: digits, useGrouping: false })));
  return format.format(value);
}

const isRecordOf = (value: object, keys: string[]) => keys.every((key) => typeof (value as Record<string, unknown>)[key] === 'number');

/**
 * What a learner's function returned, or a case's answer, spelled out: numbers to 6 digits,
 * vectors and colours as (x, y, z) in the reader's number format, text in quotes, anything
 * else by its kind ("null", "undefined", "array", "object").
 */
export function labValue(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number') return labNumber(value);
  if (value === null || value === undefined || typeof value === 'boolean') return String(value);
  if (Array.isArray(value)) return 'array';
  if (typeof value !== 'object') return typeof value;
  const parts = value as Record<string, number>;
  if (isRecordOf(value, ['x', 'y', 'z'])) return `(${numberList([parts.x!, parts.y!, parts.z!].map((part) => labNumber(part)))})`;
  if (isRecordOf(value, ['r', 'g', 'b'])) return `(${numberList([parts.r!, parts.g!, parts.b!].map((part) => labNumber(part)))})`;
  return 'object';
}
