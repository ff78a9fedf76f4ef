import { currentLocale } from './locale.ts';

/**
 * Numbers as the reader's language writes them: 8.624 and 0,5 in Dutch, 8,624 and 0.5 in
 * English (a Dutch pupil reads "8,624" as eight and a bit). The formatter is made per
 * language on first use, so a module may keep one in a constant and still follow a change
 * of language. Data written for machines (CSV, JSON, scene files) keeps plain JavaScript
 * numbers instead.
 */
export function localNumbers(options: Intl.NumberFormatOptions = {}): { format(value: number): string } {
  const made = new Map<string, Intl.NumberFormat>();
  return {
    format(value: number): string {
      const locale = currentLocale();
      let format = made.get(locale);
      if (!format) made.set(locale, (format = new Intl.NumberFormat(locale, options)));
      return format.format(value);
    },
  };
}

const fieldFormats = new Map<string, Intl.NumberFormat>();

/**
 * `value` with exactly `decimals` decimals as the reader's language writes it, without
 * thousands separators: "1000,50" in Dutch, "1000.50" in English. For fields a learner
 * edits and reads back, where "1.000" would read as one in English and 1000 in Dutch.
 */
export function fieldNumber(value: number, decimals: number): string {
  const key = `${currentLocale()} ${decimals}`;
  let format = fieldFormats.get(key);
  if (!format) {
    format = new Intl.NumberFormat(currentLocale(), { minimumFractionDigits: decimals, maximumFractionDigits: decimals, useGrouping: false });
    fieldFormats.set(key, format);
  }
  return format.format(value);
}

/**
 * Numbers written one after another, as in a vector "(0.5, 1, 2)": joined by ", " in English
 * and by "; " in Dutch, where the comma is the decimal sign ("(0,5; 1; 2)").
 */
export function numberList(texts: readonly string[]): string {
  return texts.join(currentLocale() === 'nl' ? '; ' : ', ');
}
