import type { Camera, Light, LightType, Material, RenderSettings, Scene, SceneObject, ShapeKind } from '../scene/scene.ts';
import type { BvhViewOptions, GizmoOptions, RayViewOptions, Selection } from './lab-state.ts';

/**
 * Every change to the app is one of these named actions, dispatched through the store.
 * Names are what happened ("pixel.selected"): the quest engine's goals and the timing log
 * listen for them by name, and level solutions are lists of them, run headless in tests.
 *
 * Some actions change no state (view.orbited, render.finished): they are facts the quest
 * engine and the log need, reported by the view or the render window.
 */
export type LabAction =
  | { type: 'scene.loaded'; scene: Scene }
  | { type: 'selection.changed'; selection: Selection }
  | { type: 'object.added'; shape: ShapeKind; mesh?: string }
  | { type: 'object.deleted'; id: string }
  | { type: 'object.changed'; id: string; changes: Partial<Omit<SceneObject, 'id' | 'material'>> }
  | { type: 'material.changed'; id: string; changes: Partial<Material> }
  | { type: 'light.added'; lightType: LightType }
  | { type: 'light.deleted'; id: string }
  | { type: 'light.changed'; id: string; changes: Partial<Light> }
  | { type: 'camera.changed'; changes: Partial<Camera> }
  | { type: 'settings.changed'; changes: Partial<RenderSettings> }
  | { type: 'pixel.selected'; pixel: [number, number] }
  | { type: 'pixel.deselected' }
  | { type: 'rays.changed'; changes: Partial<RayViewOptions> }
  | { type: 'gizmo.changed'; changes: Partial<GizmoOptions> }
  | { type: 'bvh.changed'; changes: Partial<BvhViewOptions> }
  | { type: 'view.orbited' }
  | { type: 'view.panned' }
  | { type: 'view.zoomed' }
  | { type: 'view.flew-to-camera' }
  | { type: 'render.started' }
  | { type: 'render.finished'; ms: number }
  | { type: 'render.cancelled' }
  | { type: 'render.saved' }
  /** The scene was saved as a file or copied as a link (the sandbox level and its badge listen). */
  | { type: 'scene.saved'; to: 'file' | 'link' }
  | { type: 'panel.opened'; panel: string };

export type LabActionType = LabAction['type'];
