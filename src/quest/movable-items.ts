import type { LabAction } from '../lab-state/lab-action.ts';
import type { Selection } from '../lab-state/lab-state.ts';

/**
 * A level's `ui.movable` (docs/levels.md): the only scene items its gizmo, the gizmo's keys
 * and Delete may change, so that a challenge that asks to move one thing keeps the rest
 * where its target picture has them. Objects and lights go by their ids, the ray tracer's
 * camera by MOVABLE_CAMERA; undefined means every item. A task's solution ("show me") keeps
 * to the same lock (a level rule): it shows what the learner can do themselves.
 */
export type MovableItems = readonly string[] | undefined;

/** The name `ui.movable` gives the ray tracer's camera. */
export const MOVABLE_CAMERA = 'camera';

/** Whether the level keeps `selection` where it is (nothing selected is never locked). */
export function isLocked(selection: Selection, movable: MovableItems): boolean {
  if (selection === null || movable === undefined) return false;
  return !movable.includes(selection.kind === 'camera' ? MOVABLE_CAMERA : selection.id);
}

/** The fields that place an item, the ones its gizmo changes (gizmo-changes.ts); the rest (a material, the camera's field of view) are its panels'. */
const PLACING_FIELDS = ['position', 'rotation', 'scale', 'size', 'target'];
const places = (changes: object) => Object.keys(changes).some((field) => PLACING_FIELDS.includes(field));

/** The locked item `action` moves, turns, scales or deletes (a level's `ui.movable`), or null when it leaves every locked item where it is. */
export function lockedItemMoved(action: LabAction, movable: MovableItems): string | null {
  if (movable === undefined) return null;
  const lockedId = (id: string) => (movable.includes(id) ? null : id);
  switch (action.type) {
    case 'object.changed':
    case 'light.changed':
      return places(action.changes) ? lockedId(action.id) : null;
    case 'object.deleted':
    case 'light.deleted':
      return lockedId(action.id);
    case 'camera.changed':
      return places(action.changes) ? lockedId(MOVABLE_CAMERA) : null;
    default:
      return null;
  }
}
