/**
 * Reading a scene from the command line: a scene file, a level file (its `scene`), or a
 * level id looked up in levels/. Problems come back as `path: reason` lines.
 */
import { readdir, readFile, stat } from 'node:fs/promises';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describeJsonError } from '../scene/json-error.ts';
import { loadMeshesFromDisk } from '../scene/load-meshes-node.ts';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import { meshNamesInScene } from '../scene/mesh-names.ts';
import { parseScene, type SceneParseResult } from '../scene/scene-schema.ts';
import type { Scene } from '../scene/scene.ts';
import { describeFileError, InputError } from './cli-errors.ts';

const LEVELS_DIR = fileURLToPath(new URL('../../levels/', import.meta.url));

export type SceneFileCheck = { ok: true; scene: Scene } | { ok: false; problems: string[] };

/**
 * Reads and checks a scene or level file. A level is recognised by its top-level `scene`
 * and `tasks` fields; only its scene is checked until the level schema arrives with the game.
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
  const result = isLevel(json) ? inLevel(parseScene(json.scene)) : parseScene(json);
  return result.ok ? result : { ok: false, problems: result.errors };
}

/** The scene named on the command line (a file or a level id); InputError when there is none or it is invalid. */
export async function readScene(fileOrLevelId: string): Promise<{ file: string; scene: Scene }> {
  const file = await findSceneFile(fileOrLevelId);
  const check = await checkSceneFile(file);
  if (!check.ok) throw new InputError(check.problems.map((problem) => `${file}: ${problem}`).join('\n'));
  return { file, scene: check.scene };
}

/** The models the scene's mesh objects use, from assets/models; InputError when one is missing. */
export async function loadSceneMeshes(scene: Scene): Promise<MeshLibrary> {
  try {
    return await loadMeshesFromDisk(meshNamesInScene(scene));
  } catch (error) {
    throw new InputError(error instanceof Error ? error.message : String(error));
  }
}

function isLevel(json: unknown): json is { scene: unknown; tasks: unknown } {
  return typeof json === 'object' && json !== null && 'scene' in json && 'tasks' in json;
}

/** Moves a scene's problems under the level's `scene` field. */
function inLevel(result: SceneParseResult): SceneParseResult {
  if (result.ok) return result;
  const errors = result.errors.map((error) => (error.startsWith('(root)') ? `scene${error.slice('(root)'.length)}` : `scene.${error}`));
  return { ok: false, errors };
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
