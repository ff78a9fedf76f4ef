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
import { toRgba8 } from '../../src/tracer/quantize.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

/**
 * Picture predictions (spec/challenges.md §1): each choice is the level's starting scene
 * changed by its actions, rendered small. A choice whose actions are refused, or two choices
 * that look the same, would ask the learner to tell apart what cannot be told apart.
 */

const pictureGoal = (choices: unknown[][], answer = 0): PictureGoal => {
  const goal = goalSchema.parse({ picture: { question: 'Which picture?', choices: choices.map((actions) => ({ actions })), answer } });
  if (goal.kind !== 'picture') throw new Error('expected a picture goal');
  return goal;
};

/** The picture as the learner sees it: the 8-bit values the quiz draws (its encoding and dithering included). */
async function render(scene: Scene): Promise<Uint8ClampedArray> {
  const [width, height] = scene.settings.imageSize;
  const tracer = buildTracerScene(scene, await loadMeshesFromDisk(meshNamesInScene(scene)));
  const rgb = renderTile(tracer, { x: 0, y: 0, width, height }, { imageWidth: width, imageHeight: height, seed: 0 });
  return toRgba8(rgb, width, height, scene.settings);
}

/** Mean absolute difference per colour channel, 0..1. */
function difference(a: Uint8ClampedArray, b: Uint8ClampedArray): number {
  let sum = 0;
  for (let i = 0; i < a.length; i++) if (i % 4 !== 3) sum += Math.abs(a[i] - b[i]);
  return sum / ((a.length * 3) / 4) / 255;
}

describe("a picture prediction's scenes", () => {
  it("are the level's starting scene changed by each choice's actions, at thumbnail size with its aspect", () => {
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
    return level.tasks.flatMap((task) => (task.goal.kind === 'picture' ? [{ name: `${level.id}/${task.id}`, scene: level.scene, goal: task.goal }] : []));
  });

describe("the levels' picture predictions", () => {
  it('are there: at least one level asks one', () => expect(pictureTasks.length).toBeGreaterThan(0));

  it.each(pictureTasks)("$name: every choice's actions are accepted, and every two pictures differ to the eye", async ({ scene, goal }) => {
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
