import type { Scene } from '../../src/scene/scene.ts';
import { sceneFrom } from './test-scene.ts';

/** The heaviest scene the schema accepts: a 2.6 kB link that used to start a render of about 38 days. */
export const heaviestScene: Scene = sceneFrom({
  settings: { maxDepth: 10, supersampling: 8, imageSize: [4096, 4096] },
  objects: Array.from({ length: 256 }, (_, i) => ({
    id: `glass-${i}`,
    position: [(i % 16) - 8, 0, Math.floor(i / 16) - 8],
    material: { transparent: true, specular: 1 },
  })),
  lights: Array.from({ length: 32 }, (_, i) => ({ id: `panel-${i}`, type: 'area', position: [i - 16, 5, 0], samples: 10 })),
});
