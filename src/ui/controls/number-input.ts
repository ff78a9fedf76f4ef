import { msg, str } from '@lit/localize';
import { fieldNumber } from '../../i18n/number-format.ts';

/**
 * Reading numbers that people type into the panels' fields (pure: no DOM, tested in Node).
 *
 * Accepted: "0.5" and "0,5" (a Dutch keyboard's decimal comma), "−2" (a typographic minus),
 * "1e3", "50%" (a hundredth, in any field), and in a percent field a bare "50" (the field
 * shows percent). When both "." and "," occur, the last one is the decimal separator and
 * the other groups thousands ("1.000,5" and "1,000.5" are both 1000.5); a lone "," is always
 * decimal, so "1,000" is 1.
 */

/** The numbers a field accepts, in the scene's units (a percent field keeps fractions 0..1). */
export interface NumberRange {
  min: number;
  max: number;
  /** Round to a whole number (counts: samples, pixels, depth). */
  whole?: boolean;
  /** The field shows value × 100 with a "%" sign. */
  percent?: boolean;
  /** Why the range ends where it does, said when typed text is clamped (the image size's limit protects the browser). */
  why?: string;
}

export type TypedNumber =
  | { kind: 'ok'; value: number }
  /** Out of range: `value` is the nearest end of the range. */
  | { kind: 'clamped'; value: number }
  /** A fraction in a whole-number field: `value` is the nearest whole number. */
  | { kind: 'rounded'; value: number }
  | { kind: 'invalid' };

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;

/** Reads typed text as a number of `range`; `unit` (such as "°" or "m") may be typed after it. */
export function parseTypedNumber(text: string, range: NumberRange, unit = ''): TypedNumber {
  let t = text
    .trim()
    .replace(/\u2212/g, '-')
    .replace(/\s+/g, '');
  const suffix = unit.replace(/\s+/g, '');
  if (suffix && suffix !== '%' && t.endsWith(suffix)) t = t.slice(0, -suffix.length);
  const typedPercent = t.endsWith('%');
  if (typedPercent) t = t.slice(0, -1);
  t = normalizeSeparators(t);
  if (!NUMBER.test(t)) return { kind: 'invalid' };
  const number = Number(t);
  const value = typedPercent || range.percent ? number / 100 : number;
  if (Number.isNaN(value)) return { kind: 'invalid' };
  if (value < range.min) return { kind: 'clamped', value: range.min };
  if (value > range.max) return { kind: 'clamped', value: range.max };
  if (range.whole && !Number.isInteger(value)) return { kind: 'rounded', value: Math.round(value) };
  return { kind: 'ok', value };
}

/**
 * The last of "." and "," is the decimal point; earlier ones must be the other sign and
 * group thousands. A repeated decimal sign ("1.2.3") gives text that is not a number.
 */
function normalizeSeparators(text: string): string {
  const point = Math.max(text.lastIndexOf('.'), text.lastIndexOf(','));
  if (point < 0) return text;
  const head = text.slice(0, point);
  if (head.includes(text[point])) return '';
  return head.replace(/[.,]/g, '') + '.' + text.slice(point + 1);
}

/**
 * The value as a field shows it, in the reader's language ("0,50" in Dutch): with as many
 * decimals as the step has ("0.50" for step 0.01), more (up to 4) when the value is finer
 * than the step, as one typed or set by a gizmo. parseTypedNumber reads it back either way.
 */
export function formatNumber(value: number, step: number, percent = false): string {
  const shown = percent ? value * 100 : value;
  const decimals = decimalsOf(percent ? step * 100 : step);
  const fine = Number(shown.toFixed(4));
  return Number(shown.toFixed(decimals)) === fine ? fieldNumber(shown, decimals) : fieldNumber(fine, decimalsOf(fine));
}

/** Decimals of a step such as 0.01 (2) or 5 (0), ignoring float noise like 0.1 × 100. */
function decimalsOf(step: number): number {
  const text = String(Number(step.toFixed(6)));
  const point = text.indexOf('.');
  return point < 0 ? 0 : text.length - point - 1;
}

/** A range end as the field shows it ("0–100 %" for a percent field, "0,001" in Dutch). */
function bound(value: number, percent: boolean | undefined): string {
  const shown = Number((percent ? value * 100 : value).toFixed(4));
  return fieldNumber(shown, decimalsOf(shown));
}

function rangeText(range: NumberRange): string {
  const text = `${bound(range.min, range.percent)}–${bound(range.max, range.percent)}`;
  return range.percent ? `${text} %` : text;
}

/** What to tell the user about typed text, or undefined when it was taken as typed. */
export function typedNumberMessage(result: TypedNumber, range: NumberRange): string | undefined {
  switch (result.kind) {
    case 'ok':
      return undefined;
    case 'clamped':
      return range.why ? msg(str`Clamped to ${rangeText(range)}: ${range.why}`) : msg(str`Clamped to ${rangeText(range)}`);
    case 'rounded':
      return msg(str`Rounded to ${result.value} (whole numbers only)`);
    case 'invalid': {
      const min = bound(range.min, range.percent);
      const max = bound(range.max, range.percent);
      return range.whole ? msg(str`Type a whole number between ${min} and ${max}`) : msg(str`Type a number between ${min} and ${max}`);
    }
  }
}

/** Typed text as a field commits it: the value (none when unreadable) and the note to show. */
export function readTypedNumber(text: string, range: NumberRange, unit = ''): { value?: number; note?: string } {
  const result = parseTypedNumber(text, range, unit);
  return { value: result.kind === 'invalid' ? undefined : result.value, note: typedNumberMessage(result, range) };
}
