/**
 * The models a `shape: "mesh"` object may name. Each one ships as assets/models/<name>.obj;
 * adding a model means adding its file and its name here (the schema, the JSON Schema and
 * the docs all follow this list).
 */
export const MESH_ASSET_NAMES = ['prism', 'capsule', 'wine-glass', 'character'] as const;

export type MeshAssetName = (typeof MESH_ASSET_NAMES)[number];
