import type { Camera, Light, LightType, Material, RenderSettings, Scene, SceneObject, ShapeKind, Vec3 } from '../scene/scene.ts';
import type { RayType } from '../tracer/ray-tree.ts';
import type { BvhViewOptions, GizmoOptions, RayViewOptions, Selection } from './lab-state.ts';

/** The terms of a hit's colour the ray debugger's equation shows (a clicked one is reported). */
export const DEBUGGER_TERMS = ['ambient', 'light-ambient', 'diffuse', 'specular', 'refract', 'reflect'] as const;
export type DebuggerTerm = (typeof DEBUGGER_TERMS)[number];

/** The ray the debugger's step highlights, as goals look at it: its kind, recursion depth and what it met. */
export interface DebuggerRay {
  type: RayType;
  /** 0 for primary rays; a light or shadow ray has the depth of the hit it leaves from. */
  depth: number;
  hit: boolean;
  /** The object it hit (a shadow ray: the object that blocks it). */
  objectId: string | null;
  lightId: string | null;
  /** The object it leaves from (light, shadow, reflected and refracted rays); null for a primary ray. */
  from: string | null;
}

/**
 * What a level, or one of its tasks, shows when it starts (docs/levels.md, "Views"): where
 * the 3D view looks, which pixel is chosen, the ray filters. The app applies it; it is never
 * something the learner did, so no goal counts it.
 */
export interface DeclaredView {
  /**
   * What the 3D view glides to fit: object or light ids, `camera` (the ray tracer's camera
   * with its screen), `pixel-rays` (the chosen pixel's whole ray path) and `rays:<column>,<row>`
   * (that pixel's rays from their first hit on, chosen or not: framed-rays.ts).
   */
  frame?: string[];
  /** The side the view looks from, towards what it frames (a world direction); by default the side it looks from now. */
  from?: Vec3;
  /** Look through the ray tracer's camera, as "Camera view" does (instead of `frame`). */
  throughCamera?: boolean;
  /** The pixel to choose, or null for none (all pixels' rays). */
  pixel?: [number, number] | null;
  /** Ray options to set; the rest stay as they are. */
  rays?: Partial<RayViewOptions>;
}

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
  /** A level's or task's declared view was applied by the app (see DeclaredView). */
  | { type: 'view.applied'; view: DeclaredView }
  | { type: 'gizmo.changed'; changes: Partial<GizmoOptions> }
  | { type: 'bvh.changed'; changes: Partial<BvhViewOptions> }
  | { type: 'view.orbited' }
  | { type: 'view.panned' }
  | { type: 'view.zoomed' }
  | { type: 'view.flew-to-camera' }
  | { type: 'render.started' }
  /** `rays`: the rays the render traced (the render window counts them; a solution's render leaves it out). */
  | { type: 'render.finished'; ms: number; rays?: number }
  | { type: 'render.cancelled' }
  | { type: 'render.saved' }
  /** A challenge's pictures were compared after a render: `difference` is challenge-closeness.ts's measure, the counts the referee's since the challenge started, this render included (quest/challenge-par.ts). */
  | { type: 'challenge.compared'; difference: number; renders: number; changes: number; rays: number }
  /** A code lab's run was graded: `passed` of `total` cases, `failed` the kind of the first that failed (code-lab-grading.ts). */
  | { type: 'code.graded'; lab: string; passed: number; total: number; failed: string | null }
  /** The scene was saved as a file or copied as a link (the sandbox level and its badge listen). */
  | { type: 'scene.saved'; to: 'file' | 'link' }
  | { type: 'panel.opened'; panel: string }
  /** The ray debugger moved to a step (`step` of `of`) that highlights `ray` (null: the pixel's average). */
  | { type: 'debugger.stepped'; step: number; of: number; ray: DebuggerRay | null }
  /** A term of the debugger's equation was clicked (its ray highlighted). */
  | { type: 'debugger.term-clicked'; term: DebuggerTerm; lightId: string | null };

export type LabActionType = LabAction['type'];

/** What the ray debugger reports (and "show me" performs through it). */
export type DebuggerAction = Extract<LabAction, { type: 'debugger.stepped' | 'debugger.term-clicked' }>;
