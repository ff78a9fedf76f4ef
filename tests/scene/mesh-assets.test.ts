import { readFileSync } from 'node:fs';
import { Box3, Triangle, Vector3 } from 'three';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { buildModels } from '../../scripts/make-models.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { MESH_ASSET_NAMES } from '../../src/scene/mesh-assets.ts';
import type { MeshData } from '../../src/scene/mesh-data.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import { sceneFrom } from '../support/test-scene.ts';

const MODELS_DIR = new URL('../../assets/models/', import.meta.url);

/** Inclusive triangle-count ranges: loose enough to retune a model, tight enough to catch a broken build. */
const TRIANGLES: Record<string, [number, number]> = {
  prism: [8, 8],
  capsule: [1000, 3000],
  'wine-glass': [2000, 10000],
  character: [5000, 15000], // the benchmark needs one mesh of at least 5,000 triangles
};

const meshes = await loadMeshesFromDisk(MESH_ASSET_NAMES);

function corner(mesh: MeshData, vertex: number): Vector3 {
  return new Vector3().fromArray(mesh.positions, 3 * vertex);
}

/**
 * The triangles' corners as position ids, where equal positions share an id: flat-shaded
 * models repeat a corner once per face, and the surface is closed only across those copies.
 */
function weldedTriangles(mesh: MeshData): number[] {
  const idByPosition = new Map<string, number>();
  return [...mesh.indices].map((vertex) => {
    const key = corner(mesh, vertex).toArray().join(',');
    if (!idByPosition.has(key)) idByPosition.set(key, idByPosition.size);
    return idByPosition.get(key) ?? -1;
  });
}

/** Each directed edge a→b and how many triangles use it. */
function directedEdgeCounts(triangles: number[]): Map<string, number> {
  const counts = new Map<string, number>();
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const edge = `${triangles[t + k]}>${triangles[t + ((k + 1) % 3)]}`;
      counts.set(edge, (counts.get(edge) ?? 0) + 1);
    }
  }
  return counts;
}

/** Signed volume (divergence theorem): positive when the faces wind counter-clockwise seen from outside. */
function signedVolume(mesh: MeshData): number {
  let volume = 0;
  for (let t = 0; t < mesh.indices.length; t += 3) {
    const [a, b, c] = [0, 1, 2].map((k) => corner(mesh, mesh.indices[t + k]));
    volume += a.dot(b.cross(c)) / 6;
  }
  return volume;
}

describe('shipped mesh models', () => {
  it('include every model make-models builds, each file as the build writes it', () => {
    const built = buildModels();
    for (const [name, text] of built) {
      expect(MESH_ASSET_NAMES).toContain(name);
      expect(readFileSync(new URL(`${name}.obj`, MODELS_DIR), 'utf8'), `${name}.obj is stale: run npx tsx scripts/make-models.ts`).toBe(text);
    }
  });

  for (const name of MESH_ASSET_NAMES) {
    describe(name, () => {
      const mesh = meshes.get(name) as MeshData;

      it('has the expected number of triangles and a file under 1 MB', () => {
        const [fewest, most] = TRIANGLES[name];
        const triangles = mesh.indices.length / 3;
        expect(triangles).toBeGreaterThanOrEqual(fewest);
        expect(triangles).toBeLessThanOrEqual(most);
        expect(readFileSync(new URL(`${name}.obj`, MODELS_DIR)).length).toBeLessThan(1024 * 1024);
      });

      it('is 1 m tall from y = -0.5, centred in X and Z, no wider than the unit shapes need', () => {
        const bounds = new Box3().setFromArray(mesh.positions);
        expect(bounds.min.y).toBeCloseTo(-0.5, 4);
        expect(bounds.max.y).toBeCloseTo(0.5, 4);
        expect(bounds.min.x + bounds.max.x).toBeCloseTo(0, 4);
        expect(bounds.min.z + bounds.max.z).toBeCloseTo(0, 4);
        expect(Math.max(bounds.max.x, bounds.max.z)).toBeLessThanOrEqual(0.6);
      });

      it('has unit normals that agree with the winding of every face', () => {
        const normals = mesh.normals;
        expect(normals).not.toBeNull();
        if (!normals) return;
        const faceNormal = new Vector3();
        const vertexNormal = new Vector3();
        const notUnit: number[] = [];
        const facingInward: number[] = [];
        for (let t = 0; t < mesh.indices.length; t += 3) {
          const [a, b, c] = [0, 1, 2].map((k) => corner(mesh, mesh.indices[t + k]));
          new Triangle(a, b, c).getNormal(faceNormal);
          for (let k = 0; k < 3; k++) {
            const vertex = mesh.indices[t + k];
            vertexNormal.fromArray(normals, 3 * vertex);
            if (Math.abs(vertexNormal.length() - 1) > 1e-5) notUnit.push(vertex);
            if (vertexNormal.dot(faceNormal) <= 0) facingInward.push(t / 3);
          }
        }
        expect(notUnit).toEqual([]);
        expect(facingInward).toEqual([]);
      });

      it('is closed and wound outward: every edge is used once in each direction', () => {
        const counts = directedEdgeCounts(weldedTriangles(mesh));
        const unmatched = [...counts].filter(([edge, count]) => {
          const [a, b] = edge.split('>');
          return count !== 1 || counts.get(`${b}>${a}`) !== 1;
        });
        expect(unmatched).toEqual([]);
        expect(signedVolume(mesh)).toBeGreaterThan(0);
      });

      it('has no zero-area triangles', () => {
        const slivers: number[] = [];
        for (let t = 0; t < mesh.indices.length; t += 3) {
          const [a, b, c] = [0, 1, 2].map((k) => corner(mesh, mesh.indices[t + k]));
          if (new Triangle(a, b, c).getArea() === 0) slivers.push(t / 3);
        }
        expect(slivers).toEqual([]);
      });
    });
  }
});

describe('loadMeshesFromDisk', () => {
  it('names the model and the file it could not read', async () => {
    await expect(loadMeshesFromDisk(['teapot'])).rejects.toThrow(/mesh "teapot": cannot read .*teapot\.obj/);
  });
});

describe('loadMeshes (browser)', () => {
  /** A fresh copy of the loader (its cache is per module) with fetch served from the repository. */
  async function browserLoader(status: (url: string) => number = () => 200) {
    const fetched: string[] = [];
    vi.stubGlobal('fetch', async (url: string) => {
      fetched.push(url);
      const code = status(url);
      return code === 200 ? new Response(readFileSync(new URL(`../..${url}`, import.meta.url), 'utf8')) : new Response('', { status: code });
    });
    vi.resetModules();
    const { loadMeshes } = await import('../../src/render/load-meshes-browser.ts');
    return { loadMeshes, fetched };
  }

  afterEach(() => {
    vi.unstubAllGlobals();
  });

  it('gives the same meshes as the disk loader, downloading each model once', async () => {
    const { loadMeshes, fetched } = await browserLoader();
    expect(await loadMeshes(MESH_ASSET_NAMES)).toEqual(meshes);
    await loadMeshes(['prism', 'prism']);
    expect(fetched.length).toBe(MESH_ASSET_NAMES.length);
  });

  it('names the model that is not shipped, and the ones that are', async () => {
    const { loadMeshes } = await browserLoader();
    await expect(loadMeshes(['teapot'])).rejects.toThrow('mesh "teapot" is not one of the shipped models (capsule, character, prism, wine-glass)');
  });

  it('reports a failed download and tries again next time', async () => {
    let failures = 1;
    const { loadMeshes, fetched } = await browserLoader(() => (failures-- > 0 ? 503 : 200));
    await expect(loadMeshes(['capsule'])).rejects.toThrow(/mesh "capsule": downloading .*capsule\.obj failed \(HTTP 503\)/);
    expect((await loadMeshes(['capsule'])).get('capsule')).toEqual(meshes.get('capsule'));
    expect(fetched.length).toBe(2);
  });
});

describe('meshNamesInScene', () => {
  it('lists each mesh asset a scene uses once, in order of first use', () => {
    const mesh = (id: string, name: string) => ({ id, shape: 'mesh', mesh: name });
    const scene = sceneFrom({
      objects: [mesh('a', 'capsule'), { id: 'ball', shape: 'sphere' }, mesh('b', 'prism'), mesh('c', 'capsule')],
    });
    expect(meshNamesInScene(scene)).toEqual(['capsule', 'prism']);
  });
});
