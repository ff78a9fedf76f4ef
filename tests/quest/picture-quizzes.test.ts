import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { goalSchema, type PictureGoal } from '../../src/quest/goal.ts';
import { levelSchema } from '../../src/quest/level-schema.ts';
import { PICTURE_WIDTH, pictureScenes } from '../../src/quest/picture-scenes.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

/**
 * Picture predictions (spec/challenges.md §1): each choice is the level's starting scene
 * changed by its actions, rendered small. A choice whose actions are refused, or two choices
 * that look the same, would ask the learner to tell apart what cannot be told apart.
 */

const pictureGoal = (choices: unknown[][], answer = 0): PictureGoal => {
  const goal = goalSchema.parse({ picture: { question: 'Which picture?', choices: choices.map((actions) => ({ actions })), answer } });
  if (!('picture' in goal)) throw new Error('expected a picture goal');
  return goal;
};

async function render(scene: Scene): Promise<Float32Array> {
  const [width, height] = scene.settings.imageSize;
  const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
  return renderTile(tracer, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 0 });
}

/** Mean absolute difference per colour channel, 0..1. */
function difference(a: Float32Array, b: Float32Array): number {
  let sum = 0;
  for (let i = 0; i < a.length; i++) sum += Math.abs(Math.min(1, a[i]) - Math.min(1, b[i]));
  return sum / a.length;
}

describe('a picture prediction\'s scenes', () => {
  it('are the level\'s starting scene changed by each choice\'s actions, at thumbnail size with its aspect', () => {
    const scene = { ...defaultScene(), settings: { ...defaultScene().settings, imageSize: [320, 240] as [number, number] } };
    const goal = pictureGoal([[{ type: 'settings.changed', changes: { shadows: false } }], [{ type: 'settings.changed', changes: { supersampling: 3 } }]]);
    const [first, second] = pictureScenes(scene, goal);
    expect(first.settings).toMatchObject({ shadows: false, supersampling: scene.settings.supersampling, imageSize: [PICTURE_WIDTH, 120] });
    expect(second.settings).toMatchObject({ shadows: scene.settings.shadows, supersampling: 3, imageSize: [PICTURE_WIDTH, 120] });
    expect(scene.settings.shadows).toBe(true); // the level's scene itself is untouched
  });
});

const levelsFolder = new URL('../../levels/', import.meta.url);
const pictureTasks = readdirSync(levelsFolder)
  .filter((name) => name.endsWith('.level.json'))
  .flatMap((name) => {
    const level = levelSchema.parse(JSON.parse(readFileSync(new URL(name, levelsFolder), 'utf8')));
    return level.tasks.flatMap((task) => ('picture' in task.goal ? [{ name: `${level.id}/${task.id}`, scene: level.scene, goal: task.goal }] : []));
  });

describe.runIf(pictureTasks.length > 0)('the levels\' picture predictions', () => {
  it.each(pictureTasks)('$name: every choice\'s actions are accepted, and every two pictures differ to the eye', async ({ scene, goal }) => {
    for (const choice of goal.picture.choices) {
      let state = initialState(scene);
      for (const action of choice.actions) {
        const reduced = reduce(state, action);
        expect(reduced.error, `${action.type} is refused`).toBeUndefined();
        state = reduced.state;
      }
    }
    const images = await Promise.all(pictureScenes(scene, goal).map(render));
    for (let a = 0; a < images.length; a++) {
      for (let b = a + 1; b < images.length; b++) {
        // 1 % of the range on average: about 2.5 levels of 255 over the whole picture.
        expect(difference(images[a], images[b]), `pictures ${a} and ${b}`).toBeGreaterThan(0.01);
      }
    }
  });
});
