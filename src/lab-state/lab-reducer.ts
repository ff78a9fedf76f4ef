import { createLight, createObject } from '../scene/scene-defaults.ts';
import { lightSchema, parseScene } from '../scene/scene-schema.ts';
import type { Light, Scene } from '../scene/scene.ts';
import type { Issue } from '../util/issue.ts';
import { sameValue } from '../util/same-value.ts';
import type { DeclaredView, LabAction } from './lab-action.ts';
import { type LabState, BVH_MAX_DEPTH, DEFAULT_BVH_VIEW, DEFAULT_GIZMO, DEFAULT_RAY_VIEW } from './lab-state.ts';

/** The next state, or the unchanged state with the reasons an action was refused. */
export type Reduction = { state: LabState; error?: Issue[] };

/**
 * Applies one action (pure: no DOM, so level solutions run headless in Node). A change
 * that would make the scene invalid (an out-of-range value, an unknown id) is refused with
 * the schema's issues (`path: reason`) and nothing is lost.
 */
export function reduce(state: LabState, action: LabAction): Reduction {
  switch (action.type) {
    case 'scene.loaded':
      // A new scene (a level, the free lab, a file) starts with a clean view: the last level's
      // ray filters, gizmo mode and boxes belonged to that level. The palette is the learner's
      // own choice of colours and stays.
      return withScene(
        {
          ...state,
          selection: null,
          selectedPixel: null,
          rays: { ...DEFAULT_RAY_VIEW, colorBlindPalette: state.rays.colorBlindPalette },
          gizmo: { ...DEFAULT_GIZMO },
          bvh: { ...DEFAULT_BVH_VIEW },
          look: null,
        },
        action.scene,
      );
    case 'selection.changed':
      return { state: { ...state, selection: action.selection } };
    case 'object.added': {
      const object = createObject(action.shape, state.scene, action.mesh);
      const next = withScene(state, { ...state.scene, objects: [...state.scene.objects, object] });
      return next.error ? next : { state: { ...next.state, selection: { kind: 'object', id: object.id } } };
    }
    case 'object.deleted':
      return withScene(
        deselect(state, action.id),
        { ...state.scene, objects: state.scene.objects.filter((o) => o.id !== action.id) },
        objectExists(state, action.id),
      );
    case 'object.changed':
      return withChange(
        state,
        mapObject(state.scene, action.id, (o) => ({ ...o, ...action.changes })),
        objectExists(state, action.id),
      );
    case 'material.changed':
      return withChange(
        state,
        mapObject(state.scene, action.id, (o) => ({ ...o, material: { ...o.material, ...action.changes } })),
        objectExists(state, action.id),
      );
    case 'light.added': {
      const light = createLight(action.lightType, state.scene);
      const next = withScene(state, { ...state.scene, lights: [...state.scene.lights, light] });
      return next.error ? next : { state: { ...next.state, selection: { kind: 'light', id: light.id } } };
    }
    case 'light.deleted':
      return withScene(
        deselect(state, action.id),
        { ...state.scene, lights: state.scene.lights.filter((l) => l.id !== action.id) },
        lightExists(state, action.id),
      );
    case 'light.changed':
      return withChange(
        state,
        { ...state.scene, lights: state.scene.lights.map((l) => (l.id === action.id ? changeLight(l, action.changes) : l)) },
        lightExists(state, action.id),
      );
    case 'camera.changed':
      return withChange(state, { ...state.scene, camera: { ...state.scene.camera, ...action.changes } });
    case 'settings.changed':
      return withChange(state, { ...state.scene, settings: { ...state.scene.settings, ...action.changes } });
    case 'pixel.selected': {
      const [x, y] = action.pixel;
      const [columns, rows] = state.scene.camera.pixels;
      if (!Number.isInteger(x) || !Number.isInteger(y) || x < 0 || y < 0 || x >= columns || y >= rows) {
        return { state, error: [{ path: 'pixel', reason: { code: 'pixelOffScreenAt', columns, rows, column: x, row: y } }] };
      }
      return { state: { ...state, selectedPixel: [x, y] } };
    }
    case 'pixel.deselected':
      return { state: { ...state, selectedPixel: null } };
    case 'rays.changed':
      return { state: { ...state, rays: { ...state.rays, ...action.changes } } };
    case 'view.applied':
      return applyView(state, action.view);
    case 'gizmo.changed':
      return { state: { ...state, gizmo: { ...state.gizmo, ...action.changes } } };
    case 'bvh.changed': {
      const { depth } = action.changes;
      if (depth !== undefined && !(Number.isInteger(depth) && depth >= 0 && depth <= BVH_MAX_DEPTH)) {
        return { state, error: [{ path: 'bvh.depth', reason: { code: 'bvhDepth', most: BVH_MAX_DEPTH, got: depth } }] };
      }
      return { state: { ...state, bvh: { ...state.bvh, ...action.changes } } };
    }
    default:
      // Facts reported by the view and the render window: nothing to change.
      return { state };
  }
}

/**
 * A declared view: its pixel and ray options, and its way of looking for the 3D view to
 * follow (`look`). A pixel outside the screen (the learner made the screen smaller) is left out
 * rather than refusing the ray options with it: the view is a courtesy, not a command.
 */
function applyView(state: LabState, view: DeclaredView): Reduction {
  const { frame, from, throughCamera, pixel, rays } = view;
  const asks = frame !== undefined || throughCamera !== undefined;
  const look = asks ? { ...(frame ? { frame } : {}), ...(from ? { from } : {}), ...(throughCamera ? { throughCamera } : {}) } : state.look;
  const next = { ...state, look, ...(rays ? { rays: { ...state.rays, ...rays } } : {}) };
  if (pixel === undefined) return { state: next };
  if (pixel === null) return { state: { ...next, selectedPixel: null } };
  const chosen = reduce(next, { type: 'pixel.selected', pixel });
  return chosen.error ? { state: next } : chosen;
}

/**
 * A change of the scene's values (the `*.changed` actions): one that leaves every value as
 * it is keeps the current scene object, so the view, the tracer and the render see no change.
 * A slider's commit repeats the value its last `input` sent, and an arrow key sends both at
 * once: a new scene object traced the camera's screen, and drew the 3D view, twice per step.
 * The changed scene shares the untouched objects of the old one, so the comparison passes
 * them by identity. (A loaded scene is new even with the same values: listeners take it as
 * a fresh start.)
 */
function withChange(state: LabState, scene: Scene, precondition?: Issue): Reduction {
  if (!precondition && sameValue(scene, state.scene)) return { state };
  return withScene(state, scene, precondition);
}

/** Validates the new scene; keeps the old state with the reasons when it is invalid. */
function withScene(state: LabState, scene: Scene, precondition?: Issue): Reduction {
  if (precondition) return { state, error: [precondition] };
  const parsed = parseScene(scene);
  if (!parsed.ok) return { state, error: parsed.errors };
  const next = { ...state, scene: parsed.scene };
  // A smaller screen may leave the selected pixel outside it.
  const [columns, rows] = parsed.scene.camera.pixels;
  if (next.selectedPixel && (next.selectedPixel[0] >= columns || next.selectedPixel[1] >= rows)) next.selectedPixel = null;
  return { state: next };
}

function mapObject(scene: Scene, id: string, change: (o: Scene['objects'][number]) => Scene['objects'][number]): Scene {
  return { ...scene, objects: scene.objects.map((o) => (o.id === id ? change(o) : o)) };
}

/** A light with changes; a new type keeps the shared fields and takes the new type's defaults for the rest. */
function changeLight(light: Light, changes: Partial<Light>): Light {
  if (changes.type === undefined || changes.type === light.type) return { ...light, ...changes } as Light;
  const { id, name, position, color, intensity, ambient, diffuse, specular, distanceAttenuation } = light;
  // A point light has no direction, so no rotation to keep.
  const rotation = 'rotation' in light && changes.type !== 'point' ? { rotation: light.rotation } : {};
  const shared = { id, position, color, intensity, ambient, diffuse, specular, distanceAttenuation, ...rotation, ...(name === undefined ? {} : { name }) };
  return lightSchema.parse({ ...shared, type: changes.type });
}

function deselect(state: LabState, id: string): LabState {
  const selection = state.selection;
  return selection && selection.kind !== 'camera' && selection.id === id ? { ...state, selection: null } : state;
}

function objectExists(state: LabState, id: string): Issue | undefined {
  return state.scene.objects.some((o) => o.id === id) ? undefined : { path: 'objects', reason: { code: 'noObject', id } };
}

function lightExists(state: LabState, id: string): Issue | undefined {
  return state.scene.lights.some((l) => l.id === id) ? undefined : { path: 'lights', reason: { code: 'noLight', id } };
}
