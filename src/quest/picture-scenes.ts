import { initialState } from '../lab-state/lab-state.ts';
import { reduce } from '../lab-state/lab-reducer.ts';
import type { Scene } from '../scene/scene.ts';
import type { PictureGoal } from './goal.ts';

/** A picture choice's width in pixels: small enough to render four in a second or two, large enough to see grain. */
export const PICTURE_WIDTH = 160;

/**
 * The scenes of a picture prediction's choices: the level's starting scene changed by each
 * choice's actions (refused actions change nothing; the level test checks none is refused),
 * at thumbnail size with the level's aspect ratio.
 */
export function pictureScenes(levelScene: Scene, goal: PictureGoal): Scene[] {
  return goal.picture.choices.map((choice) => {
    let state = initialState(levelScene);
    for (const action of choice.actions) state = reduce(state, action).state;
    const [width, height] = state.scene.settings.imageSize;
    const imageSize: [number, number] = [PICTURE_WIDTH, Math.max(1, Math.round((PICTURE_WIDTH * height) / width))];
    return { ...state.scene, settings: { ...state.scene.settings, imageSize } };
  });
}
