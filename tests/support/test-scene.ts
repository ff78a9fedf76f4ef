import { issueLine } from '../../src/util/issue.ts';
import { parseScene } from '../../src/scene/scene-schema.ts';
import type { Scene } from '../../src/scene/scene.ts';
import type { MeshLibrary } from '../../src/scene/mesh-data.ts';
import { buildTracerScene, type TracerScene } from '../../src/tracer/tracer-scene.ts';

/** A scene from a partial scene file, with the schema's defaults; fails loudly if invalid. */
export function sceneFrom(file: Record<string, unknown>): Scene {
  const result = parseScene({ version: 1, ...file });
  if (!result.ok) throw new Error(`test scene is invalid:\n${result.errors.map(issueLine).join('\n')}`);
  return result.scene;
}

export function tracerSceneFrom(file: Record<string, unknown>, meshes: MeshLibrary = new Map()): TracerScene {
  return buildTracerScene(sceneFrom(file), meshes);
}

/** A matte material that only shows what a test switches on. */
export function matte(color: [number, number, number], extra: Record<string, unknown> = {}): Record<string, unknown> {
  return { color, ambient: 0, diffuse: 1, specular: 0, shininess: 32, transparent: false, refractiveIndex: 1.5, ...extra };
}

/** A white light with no ambient term, so tests see only its diffuse and specular terms. */
export function pointLight(position: [number, number, number], extra: Record<string, unknown> = {}): Record<string, unknown> {
  return { id: 'lamp', type: 'point', position, color: [1, 1, 1], intensity: 1, ambient: 0, diffuse: 1, specular: 1, distanceAttenuation: false, ...extra };
}
