import type { MeshData } from './mesh-data.ts';
import { ObjLineReader } from './obj-line-reader.ts';

/** How an index kind is named in error messages. */
interface IndexKind {
  singular: string;
  plural: string;
}
const VERTEX: IndexKind = { singular: 'vertex', plural: 'vertices' };
const NORMAL: IndexKind = { singular: 'normal', plural: 'normals' };

/** Marks a face corner written without a normal (`f 1 2 3`, `f 1/1 2/2 3/3`). */
const NO_NORMAL = -1;

/**
 * Reads a Wavefront OBJ model into MeshData.
 *
 * Understood: `v x y z` (extra values such as w or vertex colours are ignored), `vn x y z`,
 * `f` with corners `v`, `v/vt`, `v//vn` or `v/vt/vn`, negative indices (relative to the
 * last one defined), polygons (fan-triangulated, so they should be convex) and `#` comments.
 * Every other statement (`o`, `g`, `s`, `usemtl`, `mtllib`, `vt`, …) is skipped: the tracer
 * has one material per object and no textures.
 *
 * Vertices are shared by (v, vn) pair. When any face corner has no normal, `normals` is
 * null and the tracer uses flat face normals. Normals are normalized on the way in.
 *
 * @param name - Names the file in error messages, e.g. `prism.obj line 12: …`.
 * @throws Error naming the line for malformed input, and when there are no faces at all.
 */
export function parseObj(text: string, name = 'OBJ'): MeshData {
  const reader = new ObjLineReader(text);
  const positions: number[] = [];
  const normals: number[] = [];
  // Two numbers per triangle corner: position index and normal index (or NO_NORMAL), 0-based.
  const corners: number[] = [];
  let everyCornerHasNormal = true;

  const fail = (reason: string): never => {
    throw new Error(`${name} line ${reader.lineNumber}: ${reason}`);
  };

  // Appends x y z to `into`; returns whether all three are zero (a useless normal).
  const readVector = (kind: string, into: number[]): boolean => {
    let allZero = true;
    for (let axis = 0; axis < 3; axis++) {
      if (!reader.hasWord()) fail(`${kind} needs 3 coordinates (x y z), got ${axis}`);
      const value = reader.number();
      if (!Number.isFinite(value)) fail(`${kind} coordinate "${reader.lastWord()}" is not a number`);
      into.push(value);
      allZero &&= value === 0;
    }
    return allZero;
  };

  // OBJ indices are 1-based, or negative counting back from the last one defined so far.
  const resolveIndex = (index: number, count: number, kind: IndexKind): number => {
    if (index === 0) fail(`${kind.singular} index 0 is not valid (OBJ indices start at 1)`);
    const resolved = index > 0 ? index - 1 : count + index;
    if (resolved < 0 || resolved >= count) {
      const counted = `${count} ${count === 1 ? kind.singular : kind.plural}`;
      fail(`${kind.singular} index ${index} out of range (file has ${counted} before this line)`);
    }
    return resolved;
  };

  const polygon: number[] = []; // the current face's (position, normal) pairs
  const corner = { vertex: 0, normal: 0 };
  const readFace = (): void => {
    polygon.length = 0;
    while (reader.hasWord()) {
      if (!reader.faceCorner(corner)) {
        fail(`face corner "${reader.lastWord()}" is not v, v/vt, v//vn or v/vt/vn with whole-number indices`);
      }
      polygon.push(resolveIndex(corner.vertex, positions.length / 3, VERTEX));
      if (Number.isNaN(corner.normal)) {
        everyCornerHasNormal = false;
        polygon.push(NO_NORMAL);
      } else {
        polygon.push(resolveIndex(corner.normal, normals.length / 3, NORMAL));
      }
    }
    const cornerCount = polygon.length / 2;
    if (cornerCount < 3) fail(`face needs at least 3 vertices, got ${cornerCount}`);
    // Fan from the first corner: (0, k, k + 1).
    for (let k = 1; k + 1 < cornerCount; k++) {
      corners.push(polygon[0], polygon[1], polygon[2 * k], polygon[2 * k + 1], polygon[2 * k + 2], polygon[2 * k + 3]);
    }
  };

  while (reader.nextLine()) {
    switch (reader.word()) {
      case 'v':
        readVector('vertex', positions);
        break;
      case 'vn':
        if (readVector('normal', normals)) fail('normal has zero length');
        break;
      case 'f':
        readFace();
        break;
    }
  }

  if (corners.length === 0) throw new Error(`${name}: no faces (f lines) found`);
  return shareVertices(positions, everyCornerHasNormal ? normals : null, corners);
}

/**
 * Builds the indexed mesh: one vertex per distinct (position, normal) pair, or per distinct
 * position when the mesh has no normals.
 */
function shareVertices(positions: number[], normals: number[] | null, corners: number[]): MeshData {
  // The vertices made for each position form a chain (first vertex, then each one's next);
  // a position rarely has more than a few normals, so the chains stay short.
  const firstVertexAt = new Int32Array(positions.length / 3).fill(-1);
  const nextVertex: number[] = [];
  const normalOfVertex: number[] = [];
  const cornerCount = corners.length / 2;
  const indices = new Uint32Array(cornerCount);
  const outPositions: number[] = [];
  const outNormals: number[] = [];
  for (let c = 0; c < cornerCount; c++) {
    const p = corners[2 * c];
    const n = normals ? corners[2 * c + 1] : NO_NORMAL;
    let vertex = firstVertexAt[p];
    while (vertex >= 0 && normalOfVertex[vertex] !== n) vertex = nextVertex[vertex];
    if (vertex < 0) {
      vertex = normalOfVertex.length;
      normalOfVertex.push(n);
      nextVertex.push(firstVertexAt[p]);
      firstVertexAt[p] = vertex;
      outPositions.push(positions[3 * p], positions[3 * p + 1], positions[3 * p + 2]);
      if (normals) {
        const x = normals[3 * n],
          y = normals[3 * n + 1],
          z = normals[3 * n + 2];
        const length = Math.hypot(x, y, z);
        outNormals.push(x / length, y / length, z / length);
      }
    }
    indices[c] = vertex;
  }
  return {
    positions: new Float32Array(outPositions),
    normals: normals ? new Float32Array(outNormals) : null,
    indices,
  };
}
