import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { MeshData, MeshLibrary } from './mesh-data.ts';
import { parseObj } from './obj-parser.ts';

export const MODELS_DIR = fileURLToPath(new URL('../../assets/models/', import.meta.url));

/**
 * Reads the named models from `<dir>/<name>.obj` (Node: the `rt` command and the tests;
 * the browser has its own loader in src/app).
 *
 * @param dir - Defaults to the repository's assets/models.
 * @throws Error naming the model and file when one is missing or malformed.
 */
export function loadMeshesFromDisk(names: Iterable<string>, dir = MODELS_DIR): Promise<MeshLibrary> {
  return loadEachModel(names, async (name) => parseObj(await readModelText(name, dir), `${name}.obj`));
}

/** Each named model once, loaded by `load` at the same time as the others, by name. */
export async function loadEachModel(names: Iterable<string>, load: (name: string) => Promise<MeshData>): Promise<MeshLibrary> {
  const unique = [...new Set(names)];
  const meshes = await Promise.all(unique.map(load));
  return new Map(unique.map((name, i) => [name, meshes[i]]));
}

/**
 * The text of `<dir>/<name>.obj`.
 * @throws Error naming the model and file when it cannot be read.
 */
export async function readModelText(name: string, dir: string): Promise<string> {
  const path = join(dir, `${name}.obj`);
  try {
    return await readFile(path, 'utf8');
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    throw new Error(`mesh "${name}": cannot read ${path} (${reason})`, { cause: error });
  }
}
