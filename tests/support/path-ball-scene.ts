import { matte, tracerSceneFrom } from './test-scene.ts';

/** A small path-mode room for the path views' tests: a matte ball on a floor under a square panel, 4 × 4 pixels. */
export const PATH_BALL_SCENE_FILE = {
  camera: { position: [0, 1, 3.5], target: [0, 0.5, 0], fov: 45, pixels: [4, 4] },
  settings: { integrator: 'path', background: [0.2, 0.2, 0.2], maxDepth: 4, pathSamples: 16 },
  objects: [
    { id: 'floor', shape: 'plane', scale: [3, 1, 3], material: matte([0.7, 0.7, 0.7]) },
    { id: 'ball', shape: 'sphere', position: [0, 0.5, 0], scale: [0.5, 0.5, 0.5], material: matte([0.8, 0.3, 0.3]) },
  ],
  lights: [{ id: 'panel', type: 'area', position: [0, 2, 0], size: [0.5, 0.5], color: [1, 1, 1], intensity: 5, samples: 1 }],
};

/** That room as the tracer's scene. */
export const pathBallScene = () => tracerSceneFrom(PATH_BALL_SCENE_FILE);
