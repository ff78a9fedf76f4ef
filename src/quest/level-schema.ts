import { gotOf, type Issue } from '../util/issue.ts';
import { z } from 'zod';
import { sceneSchema } from '../scene/scene-schema.ts';
import { describeIssue, issuesOf, reasonIssue, withReason } from '../scene/scene-issues.ts';
import { listOf, wholeNumberIn } from '../scene/scene-schema-parts.ts';
import { labActionSchema } from './lab-action-schema.ts';
import { declaredViewSchema } from './declared-view-schema.ts';
import { taskEvidenceSchema } from './task-evidence-schema.ts';
import { FIGURE_FILES } from './figure-files.ts';
import { goalSchema } from './goal.ts';
import { kebabId } from './kebab-id.ts';
import { isGuideTarget, LAB_CONTROLS, UI_PANELS, type GuideTarget } from './lab-controls.ts';
import { levelRules, MANDATORY_TASKS } from './level-rules.ts';
import { localizedTextSchema } from './localized-text.ts';
import { MOVABLE_CAMERA } from './movable-items.ts';
import { readJson } from '../util/read-json.ts';

/**
 * A level file (`levels/<id>.level.json`): an intro, a starting scene, which parts of the
 * lab it shows, and its tasks. docs/levels.md is the authors' guide to every field. Every
 * problem becomes a `path: reason` line, as in scene files; the rules that look at several
 * fields at once (level-rules.ts) run once every field is valid.
 */

/** Points a task gives when the level does not say: mandatory tasks are the main path, optional ones a bonus. */
export const DEFAULT_POINTS = { mandatory: 10, optional: 5 } as const;

/** Far more tasks and badges than a level of one idea has (3–10 mandatory tasks); it bounds the work of reading a damaged file. */
const TASKS_MAX = 30;
const SOLUTION_STEPS_MAX = 50;
const BADGES_MAX = 20;

/** The points a level file may give one task. */
export const TASK_POINTS: readonly [number, number] = [0, 100];

const guideTargetSchema = z.custom<GuideTarget>((value) => typeof value === 'string' && isGuideTarget(value), {
  error: (issue) => withReason(issue, { code: 'notGuideTarget', got: gotOf(issue.input) }),
});

const figureSchema = z.strictObject({
  src: z.enum(FIGURE_FILES).describe('A file in assets/figures.'),
  alt: localizedTextSchema.describe('What the figure shows, for a learner who cannot see it.'),
});

const taskSchema = z
  .strictObject({
    id: kebabId(),
    title: localizedTextSchema,
    text: localizedTextSchema.describe('The instruction: one thing to do or see.'),
    figure: figureSchema.optional().describe('A picture shown above the text, with its alt text.'),
    more: localizedTextSchema.optional().describe('"Explain more": the deeper explanation, formulas welcome.'),
    mandatory: z.boolean().default(true),
    points: wholeNumberIn(TASK_POINTS).optional(),
    goal: goalSchema,
    hints: listOf(localizedTextSchema, [0, 5]).default([]).describe('Text hints, shown one at a time (the first rung of the hint ladder).'),
    guide: guideTargetSchema.optional().describe('The control the second rung rings.'),
    solution: listOf(labActionSchema, [1, SOLUTION_STEPS_MAX]).optional().describe('The actions that complete the task: "show me" performs them.'),
    view: declaredViewSchema.optional().describe('What the lab shows when this task becomes the current one.'),
    evidence: taskEvidenceSchema.optional().describe('What the text tells the learner to look at in the 3D view (checked in the browser tests).'),
  })
  .transform((task) => ({ ...task, points: task.points ?? (task.mandatory ? DEFAULT_POINTS.mandatory : DEFAULT_POINTS.optional) }));

const uiSchema = z
  .strictObject({
    panels: z.array(z.enum(UI_PANELS)).default([]).describe('The panels shown besides the 3D view.'),
    controls: z
      .partialRecord(z.enum(UI_PANELS), z.array(z.string()).min(1))
      .optional()
      .describe('Per panel, the only controls it shows; a panel not named here shows all of them.'),
    hidden: z
      .strictObject({ debugger: localizedTextSchema.optional() })
      .optional()
      .describe('Panels every level with rays shows (the ray debugger), left out here, each with the reason why.'),
    movable: z
      .array(z.string().min(1))
      .min(1)
      .optional()
      .describe(`The only scene items the gizmo, its keys and Delete may change: object or light ids, or "${MOVABLE_CAMERA}"; without it, all of them.`),
  })
  .superRefine((ui, context) => {
    // Only the gizmo moves things: a lock without it would lock nothing the learner can reach.
    if (ui.movable && !ui.panels.includes('gizmo')) context.addIssue(reasonIssue(['movable'], ui.movable, { code: 'panelNotListed', panel: 'gizmo' }));
    for (const panel of Object.keys(ui.hidden ?? {})) {
      if (ui.panels.some((shown) => shown === panel)) {
        context.addIssue(reasonIssue(['hidden', panel], panel, { code: 'panelShownAndHidden', panel }));
      }
    }
    for (const [panel, controls] of Object.entries(ui.controls ?? {})) {
      const known: readonly string[] = LAB_CONTROLS[panel as keyof typeof LAB_CONTROLS];
      if (!ui.panels.some((shown) => shown === panel)) {
        context.addIssue(reasonIssue(['controls', panel], panel, { code: 'panelNotListed', panel }));
      }
      controls.forEach((control, index) => {
        if (!known.includes(control)) {
          // As an enum says it: one allowed value quoted, several as a list.
          const allowed = known.length === 1 ? [JSON.stringify(known[0])] : known;
          context.addIssue(reasonIssue(['controls', panel, index], control, { code: 'notAllowed', allowed, got: gotOf(control) }));
        }
      });
    }
  });

const levelBadgeSchema = z.strictObject({
  id: kebabId(),
  title: localizedTextSchema,
  text: localizedTextSchema,
  tasks: z.array(kebabId()).min(1).describe('Earned when the learner has done all of these tasks themself.'),
});

export const levelSchema = z.strictObject({
  version: z.literal(1).describe('The level format version.'),
  id: kebabId().describe('The file is levels/<id>.level.json.'),
  chapter: kebabId(),
  title: localizedTextSchema,
  intro: z.strictObject({ text: localizedTextSchema, more: localizedTextSchema.optional() }),
  scene: sceneSchema,
  ui: uiSchema.prefault({}),
  view: declaredViewSchema.optional().describe("What the lab shows when the level opens (a task's own view comes on top)."),
  tasks: listOf(taskSchema, [MANDATORY_TASKS[0], TASKS_MAX]),
  badges: listOf(levelBadgeSchema, [0, BADGES_MAX]).default([]),
});

export type Level = z.output<typeof levelSchema>;
export type Task = Level['tasks'][number];
export type LevelBadge = Level['badges'][number];
export type LevelUi = Level['ui'];

export type LevelParseResult = { ok: true; level: Level } | { ok: false; errors: Issue[] };

/** Checks a level file's parsed JSON, fills in its defaults and lists every problem. */
export function parseLevel(input: unknown): LevelParseResult {
  const result = levelSchema.safeParse(input, { error: describeIssue });
  if (!result.success) return { ok: false, errors: issuesOf(result.error.issues) };
  const problems = levelRules(result.data);
  return problems.length === 0 ? { ok: true, level: result.data } : { ok: false, errors: problems };
}

/** `parseLevel` for the text of a level file; bad JSON gives one line with its place. */
export function parseLevelJson(text: string): LevelParseResult {
  const json = readJson(text);
  return json.ok ? parseLevel(json.value) : { ok: false, errors: [json.issue] };
}
