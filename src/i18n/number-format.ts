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
