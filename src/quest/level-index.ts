import { z } from 'zod';
import { describeIssue, formatIssues } from '../scene/scene-issues.ts';
import { listOf } from '../scene/scene-schema-parts.ts';
import { kebabId } from './kebab-id.ts';
import { parseLevelJson, type Level } from './level-schema.ts';
import { localizedTextSchema, type LocalizedText } from './localized-text.ts';
import { readJson } from '../util/read-json.ts';

/**
 * `levels/index.json`: the chapters in order, each with its levels in order (Learn Git
 * Branching's grouping). Loading reads every level file it lists; a level that is missing
 * or invalid is kept in the catalog as broken, with its reasons, and the others still play.
 */

/** Far more than the game will have; lengths are checked before items (listOf), so a damaged index is refused at once. */
const CHAPTERS_MAX = 50;
const LEVELS_PER_CHAPTER_MAX = 100;

export const levelIndexSchema = z
  .strictObject({
    version: z.literal(1),
    chapters: listOf(z.strictObject({ id: kebabId(), title: localizedTextSchema, levels: listOf(kebabId(), [1, LEVELS_PER_CHAPTER_MAX]) }), [1, CHAPTERS_MAX]),
  })
  .superRefine((index, context) => {
    const seen = new Set<string>();
    const once = (id: string, path: (string | number)[]) => {
      if (seen.has(id)) context.addIssue({ code: 'custom', path, input: id, message: `"${id}" is used more than once` });
      seen.add(id);
    };
    index.chapters.forEach((chapter, c) => {
      once(chapter.id, ['chapters', c, 'id']);
      chapter.levels.forEach((id, l) => once(id, ['chapters', c, 'levels', l]));
    });
  });

export type CatalogEntry = { id: string; ok: true; level: Level } | { id: string; ok: false; errors: string[] };

export interface CatalogChapter {
  id: string;
  title: LocalizedText;
  entries: CatalogEntry[];
}

/** Every level the index lists, playable or broken, in order; `errors` are the index's own. */
export interface LevelCatalog {
  chapters: CatalogChapter[];
  errors: string[];
}

export function levelFileName(id: string): string {
  return `${id}.level.json`;
}

/**
 * Reads the index and each level file it lists. `readLevelFile` gets a file name from
 * `levelFileName` and returns its text, or undefined when there is no such file (in the
 * browser from vite's `import.meta.glob`, in Node from the file system).
 */
export function loadLevels(indexText: string, readLevelFile: (fileName: string) => string | undefined): LevelCatalog {
  const json = readJson(indexText);
  if (!json.ok) return { chapters: [], errors: [json.error] };
  const index = levelIndexSchema.safeParse(json.value, { error: describeIssue });
  if (!index.success) return { chapters: [], errors: formatIssues(index.error.issues) };
  const chapters = index.data.chapters.map((chapter) => ({
    id: chapter.id,
    title: chapter.title,
    entries: chapter.levels.map((id) => loadEntry(id, chapter.id, readLevelFile)),
  }));
  return { chapters, errors: [] };
}

function loadEntry(id: string, chapter: string, readLevelFile: (fileName: string) => string | undefined): CatalogEntry {
  const fileName = levelFileName(id);
  const text = readLevelFile(fileName);
  if (text === undefined) return { id, ok: false, errors: [`(root): there is no file levels/${fileName}`] };
  const parsed = parseLevelJson(text);
  if (!parsed.ok) return { id, ok: false, errors: parsed.errors };
  const { level } = parsed;
  const errors = [
    ...(level.id === id ? [] : [`id: must be "${id}", the name index.json lists this file under, got "${level.id}"`]),
    ...(level.chapter === chapter ? [] : [`chapter: must be "${chapter}", the chapter index.json lists it in, got "${level.chapter}"`]),
  ];
  return errors.length === 0 ? { id, ok: true, level } : { id, ok: false, errors };
}

/** The playable levels in play order. */
export function playableLevels(catalog: LevelCatalog): Level[] {
  return catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])));
}
