/**
 * How a model's BVH is built (mesh-accel.ts): three-mesh-bvh's surface area heuristic, at
 * most 4 triangles a leaf. SAH is slower to build than splitting at the centre but faster to
 * cast through, and a model is built once. Named here, apart from three-mesh-bvh, so that the
 * `rt` command keys its model cache by it (src/cli/mesh-cache.ts) without loading the library.
 */
export const MESH_BVH_BUILD = { strategy: 'SAH', targetLeafSize: 4 } as const;
