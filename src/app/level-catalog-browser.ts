import { loadLevelGuide, loadLevels, type LevelCatalog, type LevelGuide } from '../quest/level-index.ts';

/**
 * The level catalog in the browser. The files are bundled as text, not as JSON modules, so
 * a level file with a JSON mistake is still built and shows up on the map as broken, with
 * its reason, instead of breaking the build for every level.
 */
const indexText = import.meta.glob<string>('../../levels/index.json', { eager: true, query: '?raw', import: 'default' });
const levelTexts = import.meta.glob<string>('../../levels/*.level.json', { eager: true, query: '?raw', import: 'default' });

const byName = new Map(Object.entries(levelTexts).map(([path, text]) => [path.slice(path.lastIndexOf('/') + 1), text]));

/** Every level listed in levels/index.json, playable or broken. */
export function loadBrowserCatalog(): LevelCatalog {
  const index = Object.values(indexText)[0];
  if (index === undefined) return { chapters: [], errors: ['(root): levels/index.json is missing from this build'] };
  return loadLevels(index, (name) => byName.get(name));
}

/** Each level's idea and the presets of levels/index.json, for the teacher page. */
export function loadBrowserLevelGuide(): LevelGuide {
  const index = Object.values(indexText)[0];
  return index === undefined ? { ideas: {}, presets: [] } : loadLevelGuide(index);
}
