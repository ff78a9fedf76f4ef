/**
 * Reading a scene from the command line: a scene file, a level file (its `scene`), or a
 * level id looked up in levels/; `rt validate` also checks the level index. Problems come
 * back as `path: reason` lines.
 */
import { readFileSync } from 'node:fs';
import { readdir, readFile, stat } from 'node:fs/promises';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { issueLine } from '../util/issue.ts';
import { describeJsonError } from '../util/json-error.ts';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import { loadLevels } from '../quest/level-index.ts';
import { parseLevel } from '../quest/level-schema.ts';
import { parseScene } from '../scene/scene-schema.ts';
import type { Scene } from '../scene/scene.ts';
import { describeFileError, InputError } from './cli-errors.ts';
import { loadMeshesCached } from './mesh-cache.ts';

const LEVELS_DIR = fileURLToPath(new URL('../../levels/', import.meta.url));

/** A checked file: a scene or a level has a scene to trace; the level index has none. */
export type SceneFileCheck = { ok: true; scene: Scene | null } | { ok: false; problems: string[] };

/**
 * Reads and checks a scene file, a level file (recognised by its `tasks`: the whole level
 * schema, goal paths included) or the level index (recognised by its `chapters`: every
 * level it lists is loaded and checked too).
 */
export async function checkSceneFile(file: string): Promise<SceneFileCheck> {
  let text: string;
  try {
    text = (await readFile(file, 'utf8')).replace(/^\uFEFF/, ''); // a byte-order mark from Windows editors
  } catch (error) {
    return { ok: false, problems: [`cannot read: ${describeFileError(error)}`] };
  }
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    return { ok: false, problems: [describeJsonError(text)] };
  }
  if (hasField(json, 'chapters')) return checkLevelIndex(file, text);
  if (hasField(json, 'tasks')) {
    const level = parseLevel(json);
    return level.ok ? { ok: true, scene: level.level.scene } : { ok: false, problems: level.errors.map(issueLine) };
  }
  const scene = parseScene(json);
  return scene.ok ? scene : { ok: false, problems: scene.errors.map(issueLine) };
}

function checkLevelIndex(file: string, text: string): SceneFileCheck {
  const readLevelFile = (name: string) => {
    try {
      return readFileSync(join(dirname(file), name), 'utf8');
    } catch {
      return undefined;
    }
  };
  const catalog = loadLevels(text, readLevelFile);
  const broken = catalog.chapters.flatMap((chapter) =>
    chapter.entries.flatMap((entry) => (entry.ok ? [] : entry.errors.map((error) => `level "${entry.id}": ${issueLine(error)}`))),
  );
  const problems = [...catalog.errors.map(issueLine), ...broken];
  return problems.length === 0 ? { ok: true, scene: null } : { ok: false, problems };
}

/** The scene named on the command line (a file or a level id); InputError when there is none or it is invalid. */
export async function readScene(fileOrLevelId: string): Promise<{ file: string; scene: Scene }> {
  const file = await findSceneFile(fileOrLevelId);
  const check = await checkSceneFile(file);
  if (!check.ok) throw new InputError(check.problems.map((problem) => `${file}: ${problem}`).join('\n'));
  if (!check.scene) throw new InputError(`${file}: this is the level index, not a scene: name one level`);
  return { file, scene: check.scene };
}

/** The models the scene's mesh objects use, from assets/models (through the cache); InputError when one is missing. */
export async function loadSceneMeshes(scene: Scene): Promise<MeshLibrary> {
  try {
    return await loadMeshesCached(meshNamesInScene(scene));
  } catch (error) {
    throw new InputError(error instanceof Error ? error.message : String(error));
  }
}

function hasField(json: unknown, field: string): boolean {
  return typeof json === 'object' && json !== null && field in json;
}

/** An existing file as given, else levels/<id>.level.json or levels/*-<id>.level.json. */
async function findSceneFile(fileOrLevelId: string): Promise<string> {
  const isFile = await stat(fileOrLevelId).then(
    () => true,
    () => false,
  );
  const looksLikePath = /[\\/]|\.json$/i.test(fileOrLevelId);
  if (isFile || looksLikePath) return fileOrLevelId;

  const levelFiles = await readdir(LEVELS_DIR).catch(() => [] as string[]);
  const matches = levelFiles.filter((name) => name === `${fileOrLevelId}.level.json` || name.endsWith(`-${fileOrLevelId}.level.json`));
  const shown = (name: string) => relative(process.cwd(), join(LEVELS_DIR, name));
  if (matches.length === 1) return shown(matches[0]);
  if (matches.length > 1) {
    throw new InputError(`"${fileOrLevelId}" matches several levels: ${matches.map(shown).join(', ')}`);
  }
  throw new InputError(
    `no scene file or level "${fileOrLevelId}": looked for the file ${fileOrLevelId}, ` +
      `then ${shown(`${fileOrLevelId}.level.json`)} and ${shown(`*-${fileOrLevelId}.level.json`)}`,
  );
}
