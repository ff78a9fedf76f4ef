import type { Scene } from './scene.ts';

/** The mesh asset names a scene's objects use, each once, in the order they first appear. */
export function meshNamesInScene(scene: Scene): string[] {
  const names = new Set<string>();
  for (const object of scene.objects) {
    if (object.shape === 'mesh' && object.mesh !== undefined) names.add(object.mesh);
  }
  return [...names];
}
