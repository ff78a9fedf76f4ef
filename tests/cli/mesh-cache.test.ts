import { issueLine } from '../../src/util/issue.ts';
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { decodeMesh, encodeMesh, loadMeshesCached } from '../../src/cli/mesh-cache.ts';
import { createNodeRenderPool } from '../../src/cli/node-worker-port.ts';
import { loadMeshesFromDisk, MODELS_DIR } from '../../src/scene/load-meshes-node.ts';
import type { MeshData } from '../../src/scene/mesh-data.ts';
import { parseSceneJson } from '../../src/scene/scene-schema.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import type { RenderTileOptions, Tile } from '../../src/tracer/tile.ts';
import { meshAccel } from '../../src/tracer/shapes/mesh-accel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

const REFERENCE = fileURLToPath(new URL('../../bench/scenes/reference.json', import.meta.url));

let cacheDir: string;
let modelsDir: string;

beforeEach(() => {
  const root = mkdtempSync(join(tmpdir(), 'rt-mesh-cache-'));
  cacheDir = join(root, 'cache');
  modelsDir = join(root, 'models');
  mkdirSync(modelsDir);
  copyFileSync(join(MODELS_DIR, 'capsule.obj'), join(modelsDir, 'capsule.obj'));
});

afterEach(() => rmSync(join(cacheDir, '..'), { recursive: true, force: true }));

function referenceScene(): Scene {
  const parsed = parseSceneJson(readFileSync(REFERENCE, 'utf8'));
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  return parsed.scene;
}

/**
 * The reference scene's robot, loaded through the cache (read back from its file) and afresh,
 * and `tile` of the scene rendered with the fresh one; checks that the robot shows in it.
 */
async function robotRenderedAfresh(tile: Tile, options: RenderTileOptions) {
  const scene = referenceScene();
  copyFileSync(join(MODELS_DIR, 'character.obj'), join(modelsDir, 'character.obj'));
  await loadMeshesCached(['character'], modelsDir, cacheDir);
  const cached = await loadMeshesCached(['character'], modelsDir, cacheDir);
  const fresh = await loadMeshesFromDisk(['character'], modelsDir);
  const afresh = renderTile(buildTracerScene(scene, fresh), tile, options);
  const withoutRobot = { ...scene, objects: scene.objects.filter((object) => object.shape !== 'mesh') };
  expect(renderTile(buildTracerScene(withoutRobot, fresh), tile, options), 'the robot shows').not.toEqual(afresh);
  return { scene, cached, fresh, afresh };
}

const cacheFile = () => join(cacheDir, 'capsule.mesh');
const loadCapsule = async () => (await loadMeshesCached(['capsule'], modelsDir, cacheDir)).get('capsule')!;

function expectSameModel(mesh: MeshData, parsed: MeshData): void {
  expect(mesh.positions).toEqual(parsed.positions);
  expect(mesh.normals).toEqual(parsed.normals);
  expect(mesh.indices).toEqual(parsed.indices);
}

describe("the rt command's model cache", () => {
  it('parses a model and builds its BVH once, then reads both back from its file', async () => {
    const parsed = (await loadMeshesFromDisk(['capsule'], modelsDir)).get('capsule')!;
    const first = await loadCapsule();
    expectSameModel(first, parsed);
    expect(first.bvh!.roots.length).toBeGreaterThan(0);
    // A write renames a new file into place: a new inode, whatever the clock's resolution.
    const { ino, mtimeMs } = statSync(cacheFile());

    const second = await loadCapsule();
    expectSameModel(second, parsed);
    // The same tree, byte for byte, from the file (not built and written again).
    expect(second.bvh!.version).toBe(first.bvh!.version);
    expect(second.bvh!.index).toEqual(first.bvh!.index);
    expect(second.bvh!.roots.map((root) => new Uint8Array(root))).toEqual(first.bvh!.roots.map((root) => new Uint8Array(root)));
    expect(statSync(cacheFile())).toMatchObject({ ino, mtimeMs });
  });

  it('renders a scene with a cached model exactly as with the model built afresh', async () => {
    // A tile of the 512 × 512 reference image with the robot in it.
    const tile = { x: 320, y: 208, width: 16, height: 16 };
    const options = { imageWidth: 512, imageHeight: 512, seed: 0 };
    const { scene, cached, fresh, afresh } = await robotRenderedAfresh(tile, options);
    expect(cached.get('character')!.bvh).toBeDefined();
    expect(renderTile(buildTracerScene(scene, cached), tile, options)).toEqual(afresh);
    // The deserialized tree is the model's own: its box is the model's.
    expect(meshAccel(cached.get('character')!).bounds).toEqual(meshAccel(fresh.get('character')!).bounds);
  });

  it('reaches a worker thread whole: the pool renders from a cached model the image a fresh one gives', async () => {
    const { scene, cached, afresh } = await robotRenderedAfresh({ x: 0, y: 0, width: 24, height: 24 }, { imageWidth: 24, imageHeight: 24, seed: 0 });
    const pool = createNodeRenderPool(1);
    try {
      const result = await pool.render(scene, cached, { width: 24, height: 24, seed: 0, preview: false }).done;
      if (result.cancelled) throw new Error('the render was cancelled');
      expect(result.rgb).toEqual(afresh);
    } finally {
      pool.dispose();
    }
  }, 30_000);

  it('rebuilds a damaged, truncated or emptied file, and writes it again whole', async () => {
    const parsed = (await loadMeshesFromDisk(['capsule'], modelsDir)).get('capsule')!;
    await loadCapsule();
    const good = readFileSync(cacheFile());
    const flipped = Uint8Array.from(good);
    flipped[flipped.length - 100] ^= 0xff;
    for (const damaged of [flipped, good.subarray(0, good.length - 8), new Uint8Array(0), new TextEncoder().encode('not a mesh')]) {
      writeFileSync(cacheFile(), damaged);
      expectSameModel(await loadCapsule(), parsed);
      expect(readFileSync(cacheFile())).toEqual(good);
    }
  });

  it('makes a new file when the model changes', async () => {
    await loadCapsule();
    // The same model with one vertex moved: another text, another key.
    const text = readFileSync(join(modelsDir, 'capsule.obj'), 'utf8').replace(/^v (\S+)/m, (_, x: string) => `v ${Number(x) + 0.25}`);
    writeFileSync(join(modelsDir, 'capsule.obj'), text);
    const edited = (await loadMeshesFromDisk(['capsule'], modelsDir)).get('capsule')!;
    expect(edited.positions).not.toEqual((await loadMeshesFromDisk(['capsule'], MODELS_DIR)).get('capsule')!.positions);
    expectSameModel(await loadCapsule(), edited);
  });

  it('still loads the models when the cache folder cannot be written', async () => {
    // A "folder" inside a file: every write fails.
    writeFileSync(join(cacheDir, '..', 'a-file'), 'x');
    const parsed = (await loadMeshesFromDisk(['capsule'], modelsDir)).get('capsule')!;
    const mesh = (await loadMeshesCached(['capsule'], modelsDir, join(cacheDir, '..', 'a-file', 'cache'))).get('capsule')!;
    expectSameModel(mesh, parsed);
  });

  it('names a missing model as the uncached loader does', async () => {
    await expect(loadMeshesCached(['teapot'], modelsDir, cacheDir)).rejects.toThrow(/mesh "teapot": cannot read/);
  });

  it('reads a file only under its own key', async () => {
    const mesh = await loadCapsule();
    const file = encodeMesh(mesh, 'key-a');
    expect(decodeMesh(file, 'key-a')).not.toBeNull();
    expect(decodeMesh(file, 'key-b')).toBeNull();
  });
});
