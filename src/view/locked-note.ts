import { msg, str } from '@lit/localize';
import { currentLocale } from '../i18n/locale.ts';
import { itemName } from '../i18n/scene-item-names.ts';
import type { Selection } from '../lab-state/lab-state.ts';
import { MOVABLE_CAMERA } from '../quest/movable-items.ts';
import type { Scene } from '../scene/scene.ts';

/**
 * Why a selected item does not move (a level's `ui.movable` locks it), and what does: said
 * when the learner selects it and when a key tries to change it, so that a missing gizmo
 * or a key that does nothing never looks like a fault of the lab.
 */
export function lockedNote(scene: Scene, selection: Exclude<Selection, null>, movable: readonly string[]): string {
  const name = selection.kind === 'camera' ? msg("The ray tracer's camera") : itemName(scene, selection.id);
  const names = movable.map((id) => (id === MOVABLE_CAMERA ? msg("the ray tracer's camera") : itemName(scene, id)));
  const movableNames = new Intl.ListFormat(currentLocale(), { type: 'conjunction' }).format(names);
  return msg(str`${name} is locked in this level: you can move only ${movableNames}.`);
}
