import { DEFAULT_SEED } from '../../src/render/render-job.ts';
import { challengeScenes, meanLinearDifference, shownLight } from '../../src/quest/challenge-closeness.ts';
import type { ChallengeGoal } from '../../src/quest/goal.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

/** Pictures already rendered, by scene: a challenge's target is measured against many attempts, and is seeded, so once is enough. */
const rendered = new Map<string, Promise<Float32Array>>();

/** A scene's picture in linear RGB, rendered in-process at its image size with the render pool's seed (the browser's workers give the same). */
export function renderLinear(scene: Scene): Promise<Float32Array> {
  const key = JSON.stringify(scene);
  let picture = rendered.get(key);
  if (!picture) {
    picture = renderNow(scene);
    rendered.set(key, picture);
  }
  return picture;
}

async function renderNow(scene: Scene): Promise<Float32Array> {
  const [width, height] = scene.settings.imageSize;
  const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
  return renderTile(tracer, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: DEFAULT_SEED });
}

/** What the app's challenge referee measures after a render: the difference of the learner's picture from the target's. */
export async function challengeDifference(levelScene: Scene, goal: ChallengeGoal, learnerScene: Scene): Promise<number> {
  const { target, attempt } = challengeScenes(levelScene, goal, learnerScene);
  return meanLinearDifference(shownLight(await renderLinear(target), target.settings), shownLight(await renderLinear(attempt), attempt.settings));
}
