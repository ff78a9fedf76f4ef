import type { Issue } from '../util/issue.ts';
import { z } from 'zod';
import { describeIssue, issuesOf, reasonIssue } from '../scene/scene-issues.ts';
import { listOf } from '../scene/scene-schema-parts.ts';
import { chosenBy } from './chosen-schema.ts';
import { kebabId } from './kebab-id.ts';
import { parseLevelJson, type Level } from './level-schema.ts';
import { localizedTextSchema, type LocalizedText } from './localized-text.ts';
import { readJson } from '../util/read-json.ts';

/**
 * `levels/index.json`: the chapters in order, each with its levels in order (Learn Git
 * Branching's grouping). Loading reads every level file it lists; a level that is missing
 * or invalid is kept in the catalog as broken, with its reasons, and the others still play.
 *
 * For teachers it also holds each level's one idea (`ideas`, by level id: the teacher page
 * names it next to the level) and `presets`, ready-made lists of levels the teacher page
 * offers in one click. They live here, beside the chapters, so that whoever adds or
 * reorders a level keeps them true.
 */

/** Far more than the game will have; lengths are checked before items (listOf), so a damaged index is refused at once. */
const CHAPTERS_MAX = 50;
const LEVELS_PER_CHAPTER_MAX = 100;
const PRESETS_MAX = 20;
const PRESET_LEVELS_MAX = 100;
/** A level's idea is one line on the teacher page, beside its title. */
export const IDEA_MAX = 100;

// A localized text (localized-text.ts) of one short line, chosen the same way so that a problem is reported where it stands.
const ideaLine = z.string().trim().min(1).max(IDEA_MAX);
const ideaPerLocale = z.strictObject({ en: ideaLine, nl: ideaLine.optional() });
const ideaSchema: z.ZodType<LocalizedText> = chosenBy((input): z.ZodType<LocalizedText> =>
  typeof input === 'object' && input !== null && !Array.isArray(input) ? ideaPerLocale : ideaLine,
);

const presetSchema = z.strictObject({ id: kebabId(), title: localizedTextSchema, levels: listOf(kebabId(), [1, PRESET_LEVELS_MAX]) });

/** A ready-made list of levels for an assignment, in the order they are played. */
export type LevelPreset = z.output<typeof presetSchema>;

export const levelIndexSchema = z
  .strictObject({
    version: z.literal(1),
    chapters: listOf(z.strictObject({ id: kebabId(), title: localizedTextSchema, levels: listOf(kebabId(), [1, LEVELS_PER_CHAPTER_MAX]) }), [1, CHAPTERS_MAX]),
    ideas: z.record(kebabId(), ideaSchema).default({}),
    presets: listOf(presetSchema, [0, PRESETS_MAX]).default([]),
  })
  .superRefine((index, context) => {
    const seen = new Set<string>();
    const once = (id: string, path: (string | number)[]) => {
      if (seen.has(id)) context.addIssue(reasonIssue(path, id, { code: 'usedMoreThanOnce', value: id }));
      seen.add(id);
    };
    index.chapters.forEach((chapter, c) => {
      once(chapter.id, ['chapters', c, 'id']);
      chapter.levels.forEach((id, l) => once(id, ['chapters', c, 'levels', l]));
    });
    // Ideas and presets name levels the chapters list: a renamed or removed level must not leave them behind.
    const listed = (id: string, path: (string | number)[]) => {
      if (!index.chapters.some((chapter) => chapter.levels.includes(id))) context.addIssue(reasonIssue(path, id, { code: 'notInAnyChapter', id }));
    };
    for (const id of Object.keys(index.ideas)) listed(id, ['ideas', id]);
    const presetIds = new Set<string>();
    index.presets.forEach((preset, p) => {
      if (presetIds.has(preset.id)) context.addIssue(reasonIssue(['presets', p, 'id'], preset.id, { code: 'usedMoreThanOnce', value: preset.id }));
      presetIds.add(preset.id);
      preset.levels.forEach((id, l) => {
        listed(id, ['presets', p, 'levels', l]);
        if (preset.levels.indexOf(id) !== l) context.addIssue(reasonIssue(['presets', p, 'levels', l], id, { code: 'usedMoreThanOnce', value: id }));
      });
    });
  });

/** What the index tells a teacher: each level's one idea, by level id, and the presets. */
export interface LevelGuide {
  ideas: Readonly<Record<string, LocalizedText>>;
  presets: LevelPreset[];
}

export type CatalogEntry = { id: string; ok: true; level: Level } | { id: string; ok: false; errors: Issue[] };

export interface CatalogChapter {
  id: string;
  title: LocalizedText;
  entries: CatalogEntry[];
}

/** Every level the index lists, playable or broken, in order; `errors` are the index's own. */
export interface LevelCatalog {
  chapters: CatalogChapter[];
  errors: Issue[];
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
  const index = readIndex(indexText);
  if (!index.ok) return { chapters: [], errors: index.errors };
  const chapters = index.data.chapters.map((chapter) => ({
    id: chapter.id,
    title: chapter.title,
    entries: chapter.levels.map((id) => loadEntry(id, chapter.id, readLevelFile)),
  }));
  return { chapters, errors: [] };
}

/** The ideas and presets of the index; none when the index cannot be read (loadLevels says why). */
export function loadLevelGuide(indexText: string): LevelGuide {
  const index = readIndex(indexText);
  return index.ok ? { ideas: index.data.ideas, presets: index.data.presets } : { ideas: {}, presets: [] };
}

function readIndex(indexText: string): { ok: true; data: z.output<typeof levelIndexSchema> } | { ok: false; errors: Issue[] } {
  const json = readJson(indexText);
  if (!json.ok) return { ok: false, errors: [json.issue] };
  const index = levelIndexSchema.safeParse(json.value, { error: describeIssue });
  return index.success ? { ok: true, data: index.data } : { ok: false, errors: issuesOf(index.error.issues) };
}

function loadEntry(id: string, chapter: string, readLevelFile: (fileName: string) => string | undefined): CatalogEntry {
  const fileName = levelFileName(id);
  const text = readLevelFile(fileName);
  if (text === undefined) return { id, ok: false, errors: [{ path: '(root)', reason: { code: 'noLevelFile', file: `levels/${fileName}` } }] };
  const parsed = parseLevelJson(text);
  if (!parsed.ok) return { id, ok: false, errors: parsed.errors };
  const { level } = parsed;
  const errors: Issue[] = [];
  if (level.id !== id) errors.push({ path: 'id', reason: { code: 'levelIdMismatch', id, got: level.id } });
  if (level.chapter !== chapter) errors.push({ path: 'chapter', reason: { code: 'chapterMismatch', chapter, got: level.chapter } });
  return errors.length === 0 ? { id, ok: true, level } : { id, ok: false, errors };
}

/** The playable levels in play order. */
export function playableLevels(catalog: LevelCatalog): Level[] {
  return catalog.chapters.flatMap((chapter) => chapter.entries.flatMap((entry) => (entry.ok ? [entry.level] : [])));
}
