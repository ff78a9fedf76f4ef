import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Plugin } from 'vite';

/**
 * The level files as the browser gets them: one module per language,
 * `virtual:level-texts/<locale>`, mapping each file name (index.json, *.level.json) to its
 * text with every `{ "en": …, "nl": … }` text replaced by the text in that language (English
 * when the language has none). A learner loads the levels in their own language only: the
 * texts are most of the first load, and the two languages together were over its budget
 * (scripts/first-load.ts). A file that is not JSON is kept as it is, so that the game shows it
 * as broken, with its reason, instead of failing the build.
 */

const PREFIX = 'virtual:level-texts/';
const RESOLVED = `\0${PREFIX}`;

/** A localized text of a level file: an object of language codes with English among them. */
function isLocalizedText(value: object): value is Record<string, string> {
  const keys = Object.keys(value);
  return keys.includes('en') && keys.every((key) => /^[a-z]{2}$/.test(key) && typeof (value as Record<string, unknown>)[key] === 'string');
}

/** `value` with every localized text replaced by its text in `locale`. */
export function inLanguage(value: unknown, locale: string): unknown {
  if (Array.isArray(value)) return value.map((item) => inLanguage(item, locale));
  if (typeof value !== 'object' || value === null) return value;
  if (isLocalizedText(value)) return value[locale] ?? value.en;
  return Object.fromEntries(Object.entries(value).map(([key, item]) => [key, inLanguage(item, locale)]));
}

/** A level file's text in `locale`; a file that is not JSON stays as written. */
export function levelTextIn(text: string, locale: string): string {
  try {
    return JSON.stringify(inLanguage(JSON.parse(text), locale));
  } catch {
    return text;
  }
}

export function levelTextsPlugin(folder = 'levels'): Plugin {
  return {
    name: 'level-texts',
    resolveId: (id) => (id.startsWith(PREFIX) ? `\0${id}` : undefined),
    load(id) {
      if (!id.startsWith(RESOLVED)) return undefined;
      const locale = id.slice(RESOLVED.length);
      const names = readdirSync(folder).filter((name) => name === 'index.json' || name.endsWith('.level.json'));
      const texts: Record<string, string> = {};
      for (const name of names) {
        const path = join(folder, name);
        this.addWatchFile(path);
        texts[name] = levelTextIn(readFileSync(path, 'utf8'), locale);
      }
      return `export default ${JSON.stringify(texts)};`;
    },
  };
}
