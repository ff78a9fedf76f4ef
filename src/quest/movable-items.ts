import type { Selection } from '../lab-state/lab-state.ts';

/**
 * A level's `ui.movable` (docs/levels.md): the only scene items its gizmo, the gizmo's keys
 * and Delete may change, so that a challenge that asks to move one thing keeps the rest
 * where its target picture has them. Objects and lights go by their ids, the ray tracer's
 * camera by MOVABLE_CAMERA; undefined means every item.
 */
export type MovableItems = readonly string[] | undefined;

/** The name `ui.movable` gives the ray tracer's camera. */
export const MOVABLE_CAMERA = 'camera';

/** Whether the level keeps `selection` where it is (nothing selected is never locked). */
export function isLocked(selection: Selection, movable: MovableItems): boolean {
  if (selection === null || movable === undefined) return false;
  return !movable.includes(selection.kind === 'camera' ? MOVABLE_CAMERA : selection.id);
}
