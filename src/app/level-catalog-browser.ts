import { wordedIssue } from '../util/issue.ts';
import { loadLevelGuide, loadLevels, type LevelCatalog, type LevelGuide } from '../quest/level-index.ts';
import type { Locale } from '../quest/localized-text.ts';

/**
 * The level catalog in the browser. The files come as text in the learner's language
 * (scripts/level-texts-plugin.ts), not as JSON modules, so a level file with a JSON mistake
 * is still built and shows up on the map as broken, with its reason, instead of breaking the
 * build for every level. `loadLevelTexts` is awaited before the game starts and whenever the
 * language changes before a game is made (an assignment's language).
 */

let texts: { locale: Locale; files: Record<string, string> } | null = null;
let catalog: { files: Record<string, string>; catalog: LevelCatalog } | null = null;

/** Loads the level files in `locale` (each language is a module of its own). */
export async function loadLevelTexts(locale: Locale): Promise<void> {
  if (texts?.locale === locale) return;
  const files = locale === 'nl' ? (await import('virtual:level-texts/nl')).default : (await import('virtual:level-texts/en')).default;
  texts = { locale, files };
}

/** The language of the level texts loaded, or null before any are. */
export function levelTextsLocale(): Locale | null {
  return texts?.locale ?? null;
}

/** Every level listed in levels/index.json, playable or broken, in the loaded language. */
export function loadBrowserCatalog(): LevelCatalog {
  const files = texts?.files;
  if (!files) return { chapters: [], errors: [wordedIssue('(root)', 'the level texts were not loaded')] };
  if (catalog?.files !== files) {
    const index = files['index.json'];
    catalog = {
      files,
      catalog:
        index === undefined
          ? { chapters: [], errors: [wordedIssue('(root)', 'levels/index.json is missing from this build')] }
          : loadLevels(index, (name) => files[name]),
    };
  }
  return catalog.catalog;
}

/** Each level's idea and the presets of levels/index.json, for the teacher page. */
export function loadBrowserLevelGuide(): LevelGuide {
  const index = texts?.files['index.json'];
  return index === undefined ? { ideas: {}, presets: [] } : loadLevelGuide(index);
}
