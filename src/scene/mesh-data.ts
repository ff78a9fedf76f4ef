/**
 * Triangle meshes for `shape: "mesh"` objects. The models ship as OBJ files in
 * assets/models; each platform loads the text its own way (fetch in the browser,
 * the file system in Node) and `parseObj` turns it into this plain, transferable form.
 */
export interface MeshData {
  /** xyz per vertex, in the model's own unit space (centred, about 1 m tall). */
  positions: Float32Array;
  /** Per-vertex normals for smooth shading, or null for flat (face) normals. */
  normals: Float32Array | null;
  /** Three vertex indices per triangle. */
  indices: Uint32Array;
  /**
   * The model's BVH, built before (the `rt` command's cache, src/cli/mesh-cache.ts), so that
   * a worker deserializes it instead of building it; absent: the tracer builds it.
   */
  bvh?: PrebuiltBvh;
}

/**
 * A built BVH as three-mesh-bvh serializes it: the serialized format's version, its root node
 * buffers and the triangle indices in the BVH's order.
 */
export interface PrebuiltBvh {
  version: number;
  roots: ArrayBuffer[];
  index: Uint32Array;
}

/** Models by asset name, as the tracer receives them. */
export type MeshLibrary = ReadonlyMap<string, MeshData>;
