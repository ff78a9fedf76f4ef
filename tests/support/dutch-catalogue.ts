import { readFileSync } from 'node:fs';

/**
 * The UI's messages as the Dutch catalogue (xliff/nl.xlf) holds them, English source beside
 * Dutch target, for tests that check other Dutch text against the UI's words: the level
 * texts must name a control as the Dutch UI labels it, and a Dutch page must show no
 * English message. The file is written by `npm run i18n:extract` in one regular shape (one
 * `<trans-unit>` with a `<source>` and a `<target>`), so a pattern reads it.
 */

export interface CatalogueMessage {
  id: string;
  /** The text between placeholders (`Rendering ${percent} %` gives "Rendering ", " %"). */
  en: string[];
  nl: string[];
  /** True when the message has no placeholder, so `en[0]` is all of it. */
  whole: boolean;
}

const UNIT = /<trans-unit id="([^"]+)">\s*<source>([\s\S]*?)<\/source>\s*(?:<target>([\s\S]*?)<\/target>)?/g;
const PLACEHOLDER = /<x [^>]*\/>/g;

function unescapeXml(text: string): string {
  return text
    .replace(/&lt;/g, '<')
    .replace(/&gt;/g, '>')
    .replace(/&quot;/g, '"')
    .replace(/&apos;/g, "'")
    .replace(/&amp;/g, '&');
}

function parts(xml: string): string[] {
  return xml.split(PLACEHOLDER).map(unescapeXml);
}

export function readDutchCatalogue(path = new URL('../../xliff/nl.xlf', import.meta.url)): CatalogueMessage[] {
  const xml = readFileSync(path, 'utf8');
  return [...xml.matchAll(UNIT)].map(([, id, source, target]) => ({
    id,
    en: parts(source),
    nl: parts(target ?? ''),
    whole: !source.includes('<x '),
  }));
}

/** A pattern for `phrase` as a whole phrase: not inside a longer word ("Size" is not in "Sizes"). */
export function phrasePattern(phrase: string, flags = 'u'): RegExp {
  const escaped = phrase.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  return new RegExp(`(?<![\\p{L}\\p{N}])${escaped}(?![\\p{L}\\p{N}])`, flags);
}
