import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { buildTracerScene, objectBvhs, type TracerScene } from '../../src/tracer/tracer-scene.ts';
import { RaycasterObject } from './raycaster-object.ts';

/** The scene with every object replaced by its Raycaster baseline; camera, lights and shading unchanged. */
export function naiveTracerScene(scene: Scene, meshes: MeshLibrary): TracerScene {
  const objects = scene.objects.map((object) => new RaycasterObject(object, meshes));
  return { ...buildTracerScene(scene, meshes), shapes: objects, ...objectBvhs(objects) };
}
