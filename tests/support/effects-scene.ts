import type { TracerScene } from '../../src/tracer/tracer-scene.ts';
import { matte, pointLight, tracerSceneFrom } from './test-scene.ts';

/** What a test changes of the effects scene: camera and settings on top, the glossy roughness, the area light's samples per side. */
export interface EffectsChanges {
  camera?: object;
  settings?: object;
  rough?: number;
  areaSamples?: number;
}

/**
 * The distributed effects' test scene on a screen of `pixels`: a floor and a glass ball (glossy
 * at `changes.rough`), an area light of `areaSamples`² samples and a point light, with the test's
 * own `objects` after them (a mirror, a moving ball), so lens, glossy, time and area-light rays
 * all meet in a few pixels.
 */
export function effectsScene(pixels: [number, number], changes: EffectsChanges, objects: Record<string, unknown>[]): TracerScene {
  const rough = changes.rough ?? 0;
  return tracerSceneFrom({
    camera: { position: [0, 1.2, 4], target: [0, 0.4, 0], fov: 50, pixels, ...changes.camera },
    settings: { maxDepth: 3, background: [0.6, 0.7, 0.9], ...changes.settings },
    objects: [
      {
        id: 'floor',
        shape: 'plane',
        scale: [10, 1, 10],
        material: matte([0.8, 0.8, 0.8], { ambient: 0.1, specular: 0.3, roughness: rough, glossySamples: 2 }),
      },
      {
        id: 'glass',
        shape: 'sphere',
        position: [0.4, 0.5, 0.5],
        material: matte([1, 1, 1], { transparent: true, diffuse: 0.1, roughness: rough, glossySamples: 2 }),
      },
      ...objects,
    ],
    lights: [
      { id: 'panel', type: 'area', position: [0, 3, 0], size: [1, 1], samples: changes.areaSamples ?? 2, ambient: 0 },
      pointLight([2, 3, 2], { id: 'bulb', intensity: 0.5 }),
    ],
  });
}
