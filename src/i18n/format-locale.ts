import { currentLocale } from './locale.ts';

/**
 * The locale that dates, times and numbers are written in: the browser's own variant of the
 * app's language when it has one (en-GB: a 24-hour clock; nl-BE), else the language itself.
 * Dutch writes a decimal comma ("9,5 min") and a 24-hour clock either way.
 */
export function formatLocale(): string {
  const language = currentLocale();
  return navigator.languages.find((tag) => tag.split('-')[0].toLowerCase() === language) ?? language;
}
