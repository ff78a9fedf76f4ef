import { z } from 'zod';
import { DEBUGGER_TERMS, type LabAction, type LabActionType } from '../lab-state/lab-action.ts';
import { DEFAULT_BVH_VIEW, DEFAULT_RAY_VIEW } from '../lab-state/lab-state.ts';
import type { Camera, Light, Material, RenderSettings, SceneObject } from '../scene/scene.ts';
import { sceneSchema } from '../scene/scene-schema.ts';
import { withReason } from '../scene/scene-issues.ts';
import { gotOf } from '../util/issue.ts';
import { isRecord } from '../util/is-record.ts';
import { challengeCountsShape } from './challenge-par.ts';
import { declaredViewSchema } from './declared-view-schema.ts';
import { optionChanges } from './option-changes.ts';

/**
 * The app's named actions as level files write them (a task's `solution`, the `event` of a
 * goal). Checked when a level loads so that "show me" never dispatches a malformed action.
 *
 * The values of scene changes (`changes` of material.changed and the like) are checked by
 * the reducer, which refuses an invalid scene with the scene schema's own message; the
 * levels-solvable test runs every solution through it. Ray and gizmo options are not part
 * of the scene, so their changes are checked here against the options' defaults.
 */

const id = () => z.string().min(1);

/** An object of fields to change; the reducer validates the changed scene. */
const sceneChanges = <Fields>() =>
  z.custom<Partial<Fields>>((value) => isRecord(value), { error: (issue) => withReason(issue, { code: 'notFieldChanges', got: gotOf(issue.input) }) });

const selectionSchema = z
  .discriminatedUnion('kind', [
    z.strictObject({ kind: z.literal('object'), id: id() }),
    z.strictObject({ kind: z.literal('light'), id: id() }),
    z.strictObject({ kind: z.literal('camera') }),
  ])
  .nullable();

const fact = <Type extends string>(type: Type) => z.strictObject({ type: z.literal(type) });

export const labActionSchema = z.discriminatedUnion('type', [
  z.strictObject({ type: z.literal('scene.loaded'), scene: sceneSchema }),
  z.strictObject({ type: z.literal('selection.changed'), selection: selectionSchema }),
  z.strictObject({ type: z.literal('object.added'), shape: z.enum(['sphere', 'box', 'cylinder', 'plane', 'mesh']), mesh: z.string().optional() }),
  z.strictObject({ type: z.literal('object.deleted'), id: id() }),
  z.strictObject({ type: z.literal('object.changed'), id: id(), changes: sceneChanges<Omit<SceneObject, 'id' | 'material'>>() }),
  z.strictObject({ type: z.literal('material.changed'), id: id(), changes: sceneChanges<Material>() }),
  z.strictObject({ type: z.literal('light.added'), lightType: z.enum(['point', 'spot', 'area']) }),
  z.strictObject({ type: z.literal('light.deleted'), id: id() }),
  z.strictObject({ type: z.literal('light.changed'), id: id(), changes: sceneChanges<Light>() }),
  z.strictObject({ type: z.literal('camera.changed'), changes: sceneChanges<Camera>() }),
  z.strictObject({ type: z.literal('settings.changed'), changes: sceneChanges<RenderSettings>() }),
  z.strictObject({ type: z.literal('pixel.selected'), pixel: z.tuple([z.number(), z.number()]) }),
  fact('pixel.deselected'),
  z.strictObject({ type: z.literal('rays.changed'), changes: optionChanges(DEFAULT_RAY_VIEW) }),
  z.strictObject({ type: z.literal('view.applied'), view: declaredViewSchema }),
  z.strictObject({
    type: z.literal('gizmo.changed'),
    changes: z.strictObject({
      mode: z.enum(['translate', 'rotate', 'scale']).optional(),
      space: z.enum(['local', 'world']).optional(),
      snap: z.boolean().optional(),
    }),
  }),
  z.strictObject({ type: z.literal('bvh.changed'), changes: optionChanges(DEFAULT_BVH_VIEW) }),
  fact('view.orbited'),
  fact('view.panned'),
  fact('view.zoomed'),
  fact('view.flew-to-camera'),
  fact('render.started'),
  z.strictObject({ type: z.literal('render.finished'), ms: z.number().min(0), rays: z.int().min(0).optional() }),
  fact('render.cancelled'),
  fact('render.saved'),
  z.strictObject({ type: z.literal('challenge.compared'), difference: z.number().min(0), ...challengeCountsShape }),
  z.strictObject({ type: z.literal('code.graded'), lab: z.string().min(1), passed: z.int().min(0), total: z.int().min(1), failed: z.string().nullable() }),
  z.strictObject({ type: z.literal('scene.saved'), to: z.enum(['file', 'link']) }),
  z.strictObject({ type: z.literal('panel.opened'), panel: z.string().min(1) }),
  z.strictObject({
    type: z.literal('debugger.stepped'),
    step: z.int().min(0),
    of: z.int().min(1),
    ray: z
      .strictObject({
        type: z.enum(['primary', 'reflect', 'refract', 'shadow', 'light', 'area-light', 'area-shadow']),
        depth: z.int().min(0),
        hit: z.boolean(),
        objectId: id().nullable(),
        lightId: id().nullable(),
        from: id().nullable(),
      })
      .nullable(),
  }),
  z.strictObject({ type: z.literal('debugger.term-clicked'), term: z.enum(DEBUGGER_TERMS), lightId: id().nullable() }),
]);

/** The action only the app dispatches (a declared view): no goal waits for it, no solution performs it. */
export const APP_ONLY_ACTION = 'view.applied' satisfies LabActionType;

/** Every action type, for the `event` of a goal. */
export const LAB_ACTION_TYPES = labActionSchema.options.map((option) => option.shape.type.value);

/** The fields an action of this type has besides `type` (what a goal's `with` may look at). */
export function actionFields(type: LabActionType): string[] {
  const option = labActionSchema.options.find((candidate) => candidate.shape.type.value === type);
  return Object.keys(option?.shape ?? {}).filter((field) => field !== 'type');
}

type SameType<A, B> = [A] extends [B] ? ([B] extends [A] ? true : false) : false;
type Assert<T extends true> = T;

/**
 * Compile-time guard that this schema follows src/lab-state/lab-action.ts: it knows every action
 * type, and what it accepts is an LabAction. A new action in the app fails here until it is
 * added above.
 */
export type SchemaMatchesLabActions = [
  Assert<SameType<z.output<typeof labActionSchema>['type'], LabActionType>>,
  Assert<z.output<typeof labActionSchema> extends LabAction ? true : false>,
];
