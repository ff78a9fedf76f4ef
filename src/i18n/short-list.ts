import { msg, str } from '@lit/localize';

/**
 * The first `shown` items and "and N more": a message that names what is wrong stays short
 * however many things are (an assignment link with 100 unknown levels once gave a notice of
 * 6,600 characters).
 */
export function shortList(items: readonly string[], shown = 5, separator = '; '): string {
  if (items.length <= shown + 1) return items.join(separator);
  const more = items.length - shown;
  return `${items.slice(0, shown).join(separator)} ${msg(str`and ${more} more`)}`;
}
