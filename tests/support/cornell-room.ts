import type { Scene } from '../../src/scene/scene.ts';
import { matte, sceneFrom } from './test-scene.ts';

const wall = (id: string, position: number[], rotation: number[], color: [number, number, number]) => ({
  id,
  shape: 'plane',
  position,
  rotation,
  scale: [2, 1, 2],
  material: matte(color),
});

/**
 * A Cornell-like room in path mode: white floor, ceiling and back wall, a red and a green
 * wall, a white box, a glass ball and a mirror ball, lit by one panel in the ceiling; `settings`
 * on top of its own.
 */
export function cornellRoom(settings: Record<string, unknown> = {}): Scene {
  const white: [number, number, number] = [0.73, 0.73, 0.73];
  return sceneFrom({
    camera: { position: [0, 1, 3.75], target: [0, 1, 0], fov: 40, pixels: [8, 8] },
    settings: { integrator: 'path', pathSamples: 8, maxDepth: 4, background: [0, 0, 0], ...settings },
    objects: [
      wall('floor', [0, 0, 0], [0, 0, 0], white),
      wall('ceiling', [0, 2, 0], [180, 0, 0], white),
      wall('back-wall', [0, 1, -1], [90, 0, 0], white),
      wall('left-wall', [-1, 1, 0], [0, 0, -90], [0.65, 0.05, 0.05]),
      wall('right-wall', [1, 1, 0], [0, 0, 90], [0.12, 0.45, 0.15]),
      { id: 'box', shape: 'box', position: [-0.35, 0.45, -0.3], rotation: [0, 20, 0], scale: [0.5, 0.9, 0.5], material: matte(white) },
      { id: 'glass', shape: 'sphere', position: [0.4, 0.3, 0.3], scale: [0.3, 0.3, 0.3], material: matte(white, { transparent: true }) },
      { id: 'mirror', shape: 'sphere', position: [0.45, 0.25, -0.5], scale: [0.25, 0.25, 0.25], material: matte(white, { specular: 0.8 }) },
    ],
    lights: [{ id: 'panel', type: 'area', position: [0, 1.99, 0], size: [0.5, 0.5], color: [1, 1, 1], intensity: 15, ambient: 0 }],
  });
}
