import { createHash, randomUUID } from 'node:crypto';
import { mkdir, readFile, rename, rm, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { MeshData, MeshLibrary } from '../scene/mesh-data.ts';
import { loadEachModel, MODELS_DIR, readModelText } from '../scene/load-meshes-node.ts';
import { parseObj } from '../scene/obj-parser.ts';
import { MESH_BVH_BUILD } from '../tracer/shapes/mesh-bvh-build.ts';

/**
 * The `rt` command's models, parsed and with their BVHs built, kept in build/mesh-cache/
 * between runs. A small render of a scene with a model spent most of its time on them: the
 * 8 624-triangle character took 50–60 ms to parse and 65–105 ms to build its BVH, each run
 * anew in a cold JIT, of a 16 × 16 render's 450–580 ms.
 *
 * A file is used only when its key matches, the hash of the model's OBJ text and the BVH's
 * build options, so an edited model makes a new one; and each new build of the command
 * (scripts/node-build.mjs, made whenever its code or three-mesh-bvh changed) empties the
 * folder, so a changed parser or builder does too. A checksum guards the rest: a damaged,
 * truncated or foreign file is rebuilt and replaced, and a folder that cannot be written only
 * costs the time the cache would have saved. (Relative to this file, so that the bundled
 * command, two folders below the root as the sources are, finds the same folder.)
 */
export const MESH_CACHE_DIR = fileURLToPath(new URL('../../build/mesh-cache/', import.meta.url));

/** The file's first bytes: what it is, and the version of its layout. */
const MAGIC = 'RTQMESH1';
/** Every section starts on a multiple of 8 bytes. */
const ALIGN = 8;

interface Header {
  key: string;
  /** Of the BVH as three-mesh-bvh serialized it. */
  bvhVersion: number;
  /** positions, normals (0 when flat), indices, the BVH's index, then its roots' byte lengths. */
  lengths: number[];
  /** SHA-1 of the lengths and everything after the header, hex (checksumOf). */
  checksum: string;
}

/** Like loadMeshesFromDisk, through the cache: the same models, each with its built BVH. */
export function loadMeshesCached(names: Iterable<string>, modelsDir = MODELS_DIR, cacheDir = MESH_CACHE_DIR): Promise<MeshLibrary> {
  return loadEachModel(names, (name) => loadMeshCached(name, modelsDir, cacheDir));
}

async function loadMeshCached(name: string, modelsDir: string, cacheDir: string): Promise<MeshData> {
  const text = await readModelText(name, modelsDir);
  const key = createHash('sha1')
    .update(text)
    .update(`\n${JSON.stringify(MESH_BVH_BUILD)}`)
    .digest('hex');
  const file = join(cacheDir, `${name}.mesh`);
  const cached = await readFile(file).then(
    (bytes) => decodeMesh(bytes, key),
    () => null,
  );
  if (cached) return cached;
  const mesh = parseObj(text, `${name}.obj`);
  // Loaded only now: a run that finds its models cached never compiles three.js and three-mesh-bvh.
  const { prebuiltBvh } = await import('../tracer/shapes/mesh-accel.ts');
  mesh.bvh = prebuiltBvh(mesh);
  // Not written (a read-only checkout, a full disk): the render goes on, and the next run builds again.
  await writeAtomically(file, encodeMesh(mesh, key)).catch(() => {});
  return mesh;
}

/**
 * Written beside its place under a name of its own and renamed into it: a command running at
 * the same time reads the old file or the new one. A file left half-written is removed.
 */
async function writeAtomically(file: string, bytes: Uint8Array): Promise<void> {
  await mkdir(join(file, '..'), { recursive: true });
  const temporary = `${file}.${randomUUID()}.tmp`;
  try {
    await writeFile(temporary, bytes);
    await rename(temporary, file);
  } catch (error) {
    await rm(temporary, { force: true });
    throw error;
  }
}

/** The cache file of `mesh` (which has its BVH): MAGIC, the header's length, the header as JSON, then the arrays. */
export function encodeMesh(mesh: MeshData, key: string): Uint8Array {
  const bvh = mesh.bvh!;
  const sections: ArrayBufferView[] = [
    mesh.positions,
    mesh.normals ?? new Float32Array(0),
    mesh.indices,
    bvh.index,
    ...bvh.roots.map((root) => new Uint8Array(root)),
  ];
  const payload = new Uint8Array(sections.reduce((size, section) => size + padded(section.byteLength), 0));
  let at = 0;
  for (const section of sections) {
    payload.set(new Uint8Array(section.buffer, section.byteOffset, section.byteLength), at);
    at += padded(section.byteLength);
  }
  const lengths = sections.map((section) => section.byteLength);
  const header: Header = { key, bvhVersion: bvh.version, lengths, checksum: checksumOf(lengths, payload) };
  const json = new TextEncoder().encode(JSON.stringify(header));
  const start = padded(MAGIC.length + 4 + json.length);
  const file = new Uint8Array(start + payload.length);
  file.set(new TextEncoder().encode(MAGIC));
  new DataView(file.buffer).setUint32(MAGIC.length, json.length, true);
  file.set(json, MAGIC.length + 4);
  file.set(payload, start);
  return file;
}

/** The mesh in a cache file, or null when the file is not one for `key` or does not hold together. */
export function decodeMesh(bytes: Uint8Array, key: string): MeshData | null {
  // A plain view: a Node Buffer's slice() would share memory instead of copying.
  const file = new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  try {
    if (file.length < MAGIC.length + 4 || new TextDecoder().decode(file.subarray(0, MAGIC.length)) !== MAGIC) return null;
    const jsonLength = new DataView(file.buffer, file.byteOffset, file.length).getUint32(MAGIC.length, true);
    const start = padded(MAGIC.length + 4 + jsonLength);
    if (start > file.length) return null;
    const header = JSON.parse(new TextDecoder().decode(file.subarray(MAGIC.length + 4, MAGIC.length + 4 + jsonLength))) as Partial<Header>;
    const { lengths, bvhVersion } = header;
    if (header.key !== key || !Number.isInteger(bvhVersion) || !Array.isArray(lengths) || lengths.length < 5) return null;
    if (!lengths.every((length) => Number.isInteger(length) && length >= 0 && length % 4 === 0)) return null;
    const payload = file.subarray(start);
    if (lengths.reduce((size, length) => size + padded(length), 0) !== payload.length || checksumOf(lengths, payload) !== header.checksum) return null;
    // Copies, each in a buffer of its own: they are sent to workers and kept there.
    const sections: ArrayBuffer[] = [];
    let at = 0;
    for (const length of lengths) {
      sections.push(payload.slice(at, at + length).buffer);
      at += padded(length);
    }
    const [positions, normals, indices, bvhIndex, ...roots] = sections;
    const mesh: MeshData = {
      positions: new Float32Array(positions),
      normals: normals.byteLength > 0 ? new Float32Array(normals) : null,
      indices: new Uint32Array(indices),
      bvh: { version: bvhVersion!, index: new Uint32Array(bvhIndex), roots },
    };
    return holdsTogether(mesh) ? mesh : null;
  } catch {
    return null;
  }
}

/** The counts agree with each other: whole triangles, a normal per vertex, the BVH's index a reordering of as many. */
function holdsTogether({ positions, normals, indices, bvh }: MeshData): boolean {
  return (
    positions.length % 3 === 0 &&
    (normals === null || normals.length === positions.length) &&
    indices.length % 3 === 0 &&
    bvh!.index.length === indices.length &&
    bvh!.roots.length > 0
  );
}

function padded(length: number): number {
  return Math.ceil(length / ALIGN) * ALIGN;
}

/** SHA-1 of the sections' lengths and the payload: a file whose numbers were altered in either fails it. */
function checksumOf(lengths: number[], payload: Uint8Array): string {
  return createHash('sha1').update(JSON.stringify(lengths)).update(payload).digest('hex');
}
