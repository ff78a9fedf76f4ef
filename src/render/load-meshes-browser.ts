import { msg, str } from '@lit/localize';
import type { MeshData, MeshLibrary } from '../scene/mesh-data.ts';
import { parseObj } from '../scene/obj-parser.ts';

/**
 * The URL of every shipped model, by asset name. Vite copies each OBJ into the build
 * (hashed, so browsers may cache it for good; one under 4 KB, like the prism, becomes a
 * data: URL) and gives us its URL, so a model is only downloaded when a scene needs it.
 */
const MODEL_URLS: ReadonlyMap<string, string> = new Map(
  Object.entries(import.meta.glob<string>('../../assets/models/*.obj', { query: '?url', import: 'default', eager: true })).map(([path, url]) => [
    path.slice(path.lastIndexOf('/') + 1, -'.obj'.length),
    url,
  ]),
);

/** One download and parse per model for the page's lifetime; a failed one is retried next time. */
const loading = new Map<string, Promise<MeshData>>();

/**
 * Fetches and parses the named models (browser).
 *
 * Every call returns the same cached MeshData objects: copy their arrays when posting them
 * to a worker rather than transferring them, or the cache is left holding detached buffers.
 *
 * @throws Error naming the model when it is not shipped, cannot be downloaded or is malformed.
 */
export async function loadMeshes(names: Iterable<string>): Promise<MeshLibrary> {
  const unique = [...new Set(names)].sort();
  const key = unique.join('\n');
  const known = libraries.get(key);
  if (known) return known;
  const meshes = await Promise.all(unique.map(loadMesh));
  const library: MeshLibrary = new Map(unique.map((name, i) => [name, meshes[i]]));
  libraries.set(key, library);
  return library;
}

/**
 * The same library object for the same set of names: the render pool reloads its workers'
 * scene when it is handed a different library object, even one with the same models.
 */
const libraries = new Map<string, MeshLibrary>();

function loadMesh(name: string): Promise<MeshData> {
  let mesh = loading.get(name);
  if (!mesh) {
    mesh = fetchMesh(name);
    mesh.catch(() => loading.delete(name));
    loading.set(name, mesh);
  }
  return mesh;
}

async function fetchMesh(name: string): Promise<MeshData> {
  const url = MODEL_URLS.get(name);
  if (url === undefined) {
    throw new Error(msg(str`mesh "${name}" is not one of the shipped models (${[...MODEL_URLS.keys()].join(', ')})`));
  }
  const response = await fetch(url);
  if (!response.ok) throw new Error(msg(str`mesh "${name}": downloading ${url} failed (HTTP ${response.status})`));
  return parseObj(await response.text(), `${name}.obj`);
}
