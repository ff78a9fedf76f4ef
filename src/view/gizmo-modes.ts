import type { GizmoOptions, Selection } from '../lab-state/lab-state.ts';
import type { Scene } from '../scene/scene.ts';

// The gizmo's modes apart from its three.js drags (gizmo-changes.ts): the toolbar and the
// panels need them before the 3D view (and three.js) has loaded.

export type GizmoMode = GizmoOptions['mode'];

/** Every gizmo mode, in the toolbar's order. */
export const GIZMO_MODES: readonly GizmoMode[] = ['translate', 'rotate', 'scale'];

/**
 * The gizmo modes that mean something for a selection: a point light has no direction and
 * no size; spot lights and the camera can turn but not grow; an area light's scale is its size.
 */
export function gizmoModesFor(selection: Selection, scene: Scene): readonly GizmoMode[] {
  if (selection === null) return [];
  if (selection.kind === 'camera') return ['translate', 'rotate'];
  if (selection.kind === 'object') return GIZMO_MODES;
  const light = scene.lights.find((l) => l.id === selection.id);
  if (!light) return [];
  if (light.type === 'point') return ['translate'];
  if (light.type === 'spot') return ['translate', 'rotate'];
  return GIZMO_MODES;
}

/** The chosen mode when the selection allows it, else moving (which every selection allows). */
export function effectiveGizmoMode(mode: GizmoMode, allowed: readonly GizmoMode[]): GizmoMode {
  return allowed.includes(mode) ? mode : 'translate';
}
