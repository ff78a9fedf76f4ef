import { mergeGeometries } from 'three/examples/jsm/utils/BufferGeometryUtils.js';
import { MeshBVH, SAH } from 'three-mesh-bvh';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { objectToWorld } from '../../src/tracer/tracer-scene.ts';
import { tessellate } from './tessellate.ts';

/**
 * The whole scene as one world-space triangle soup in one three-mesh-bvh BVH: the fastest
 * way to cast rays with the library alone (raycastFirst, no per-object transforms).
 */
export function mergedWorldBvh(scene: Scene, meshes: MeshLibrary): MeshBVH {
  const parts = scene.objects.map((object) => {
    const geometry = tessellate(object, meshes);
    geometry.deleteAttribute('normal');
    geometry.deleteAttribute('uv');
    return geometry.applyMatrix4(objectToWorld(object));
  });
  const merged = mergeGeometries(parts);
  return new MeshBVH(merged, { strategy: SAH, targetLeafSize: 4 });
}
