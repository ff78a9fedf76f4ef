import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Plugin } from 'vite';
import { LATER_TEXT_KEY } from '../src/quest/later-text-key.ts';

/**
 * The level files as the browser gets them: one module per language,
 * `virtual:level-texts/<locale>`, mapping each file name (index.json, *.level.json) to its
 * text with every `{ "en": …, "nl": … }` text replaced by the text in that language (English
 * when the language has none). A learner loads the levels in their own language only: the
 * texts are most of the first load, and the two languages together were over its budget
 * (scripts/first-load.ts). A file that is not JSON is kept as it is, so that the game shows it
 * as broken, with its reason, instead of failing the build.
 *
 * The "Explain more" texts (a level's and each task's `more`) are a fifth of those texts and
 * are read only when a learner opens one: they go to a second module per language,
 * `virtual:level-more/<locale>`, loaded on that click, and stand in the level as
 * `@later:<file>#<place>` (src/quest/later-text-key.ts; src/app/later-level-texts.ts).
 */

const PREFIX = 'virtual:level-texts/';
const RESOLVED = `\0${PREFIX}`;
const MORE_PREFIX = 'virtual:level-more/';
const MORE_RESOLVED = `\0${MORE_PREFIX}`;

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

/**
 * A level file's text in `locale` with its "Explain more" texts taken out into `later`, each
 * replaced by its key; a file that is not JSON stays as written.
 */
export function levelTextWithoutMore(name: string, text: string, locale: string, later: Record<string, string>): string {
  let level: unknown;
  try {
    level = inLanguage(JSON.parse(text), locale);
  } catch {
    return text;
  }
  const takeMore = (owner: unknown, place: string) => {
    if (typeof owner !== 'object' || owner === null) return;
    const holder = owner as { more?: unknown };
    if (typeof holder.more !== 'string') return;
    const key = `${name}#${place}`;
    later[key] = holder.more;
    holder.more = `${LATER_TEXT_KEY}${key}`;
  };
  if (typeof level === 'object' && level !== null) {
    const { intro, tasks } = level as { intro?: unknown; tasks?: unknown };
    takeMore(intro, 'intro');
    if (Array.isArray(tasks)) tasks.forEach((task, index) => takeMore(task, `task-${index}`));
  }
  return JSON.stringify(level);
}

export function levelTextsPlugin(folder = 'levels'): Plugin {
  return {
    name: 'level-texts',
    resolveId: (id) => (id.startsWith(PREFIX) || id.startsWith(MORE_PREFIX) ? `\0${id}` : undefined),
    load(id) {
      const more = id.startsWith(MORE_RESOLVED);
      if (!id.startsWith(RESOLVED) && !more) return undefined;
      const locale = id.slice((more ? MORE_RESOLVED : RESOLVED).length);
      const names = readdirSync(folder).filter((name) => name === 'index.json' || name.endsWith('.level.json'));
      const texts: Record<string, string> = {};
      const later: Record<string, string> = {};
      for (const name of names) {
        // Absolute: in the dev server a watched file's relative path is resolved as an import of this module.
        const path = resolve(folder, name);
        this.addWatchFile(path);
        texts[name] = levelTextWithoutMore(name, readFileSync(path, 'utf8'), locale, later);
      }
      return `export default ${JSON.stringify(more ? later : texts)};`;
    },
  };
}
