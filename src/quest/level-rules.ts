import { initialState, type LabState } from '../lab-state/lab-state.ts';
import type { DeclaredView } from '../lab-state/lab-action.ts';
import { framedRaysPixel } from '../lab-state/framed-rays.ts';
import type { Scene } from '../scene/scene.ts';
import { formatPath } from '../scene/scene-issues.ts';
import { gotOf, wordedIssue, type Issue, type Reason } from '../util/issue.ts';
import { FRAMED_PARTS } from './declared-view-schema.ts';
import { goalParts, kindOfGoal, type Goal } from './goal.ts';
import { APP_ONLY_ACTION } from './lab-action-schema.ts';
import { ALWAYS_SHOWN, partsOfTarget, type GuideTarget } from './lab-controls.ts';
import type { Level } from './level-schema.ts';
import { lockedItemMoved, MOVABLE_CAMERA } from './movable-items.ts';
import { problemWithPath } from './state-path.ts';
import type { TaskEvidence } from './task-evidence-schema.ts';

/**
 * The checks of a level that look at more than one field: ids, how many tasks are
 * mandatory, whether goals point at parts of the state that exist, whether a guide rings a
 * control the level shows. They run on a level whose fields are all valid.
 */

/** The mandatory tasks a level must have (spec: one idea per level, 3–10 tasks to do and see it). */
export const MANDATORY_TASKS: readonly [fewest: number, most: number] = [3, 10];

/** A problem with its reason as data (src/util/issue.ts), or as English words (state-path.ts's, not coded yet). */
interface Problem {
  path: (string | number)[];
  reason: Reason | string;
}

/** Every problem, with its path, like the schema's. */
export function levelRules(level: Level): Issue[] {
  const sample = sampleState(level.scene);
  const problems = [
    ...listedOnce(
      level.tasks.map((task) => task.id),
      ['tasks'],
      'id',
    ),
    ...listedOnce(
      level.badges.map((badge) => badge.id),
      ['badges'],
      'id',
    ),
    ...listedOnce(level.ui.panels, ['ui', 'panels']),
    ...listedOnce(level.ui.movable ?? [], ['ui', 'movable']),
    ...movableProblems(level),
    ...lockedBySolutionProblems(level),
    ...mandatoryCount(level),
    ...level.tasks.flatMap((_, index) => taskProblems(level, index, sample)),
    ...pixelPickingProblems(level),
    ...(level.view ? viewProblems(level.scene, level.view, ['view']) : []),
    ...level.tasks.flatMap((task, index) => (task.view ? viewProblems(level.scene, task.view, ['tasks', index, 'view']) : [])),
    ...level.tasks.flatMap((task, index) => (task.evidence ? evidenceProblems(level.scene, task.evidence, ['tasks', index, 'evidence']) : [])),
    ...badgeProblems(level),
  ];
  return problems.map(({ path, reason }): Issue => (typeof reason === 'string' ? wordedIssue(formatPath(path), reason) : { path: formatPath(path), reason }));
}

/** `values` name each thing once; the second, third… use is reported where it stands. */
function listedOnce(values: readonly string[], listPath: (string | number)[], field?: string): Problem[] {
  const seen = new Set<string>();
  return values.flatMap((value, index) => {
    if (!seen.has(value)) {
      seen.add(value);
      return [];
    }
    return [{ path: [...listPath, index, ...(field ? [field] : [])], reason: { code: 'usedMoreThanOnce', value } }];
  });
}

function mandatoryCount(level: Level): Problem[] {
  const count = level.tasks.filter((task) => task.mandatory).length;
  const [fewest, most] = MANDATORY_TASKS;
  if (count >= fewest && count <= most) return [];
  return [{ path: ['tasks'], reason: { code: 'mandatoryTasks', fewest, most, count } }];
}

function taskProblems(level: Level, index: number, sample: LabState): Problem[] {
  const task = level.tasks[index];
  const at = (...path: (string | number)[]) => ['tasks', index, ...path];
  const problems: Problem[] = [];
  const kind = kindOfGoal(task.goal);
  if (kind === 'do') {
    // A code lab offers no "show me" (spec/code-labs.md §1): its last hint may show a line, never the whole function.
    if (!task.solution && task.goal.kind !== 'code') problems.push({ path: at('solution'), reason: { code: 'solutionRequired' } });
    if (task.hints.length === 0) problems.push({ path: at('hints'), reason: { code: 'hintRequired' } });
    task.solution?.forEach((action, step) => {
      if (action.type === APP_ONLY_ACTION) problems.push({ path: at('solution', step), reason: { code: 'viewInSolution' } });
    });
  } else if (task.solution) {
    problems.push({ path: at('solution'), reason: { code: 'solutionNotAllowed', kind } });
  }
  if (kind === 'info' && !task.mandatory) problems.push({ path: at('mandatory'), reason: { code: 'infoNotMandatory' } });

  for (const { goal, path } of goalParts(task.goal, at('goal'))) problems.push(...statePathProblems(goal, path, sample));
  if (task.guide) problems.push(...guideProblems(level, task.guide).map((reason) => ({ path: at('guide'), reason })));
  // A challenge's controls are the only way to the target: the learner must be able to see them.
  if (task.goal.kind === 'challenge') {
    task.goal.challenge.editable.forEach((control, place) =>
      problems.push(...guideProblems(level, control).map((reason) => ({ path: at('goal', 'challenge', 'editable', place), reason }))),
    );
  }
  return problems;
}

/** A goal's paths into the state must lead somewhere in the level's state. */
function statePathProblems(goal: Goal, path: (string | number)[], sample: LabState): Problem[] {
  switch (goal.kind) {
    case 'state':
      return pathProblem(goal.state, sample, [...path, 'state']);
    case 'event':
      // `with` looks into the action, which goal.ts checks against the action's fields.
      return Object.keys(goal.where ?? {}).flatMap((statePath) => pathProblem(statePath, sample, [...path, 'where', statePath]));
    // A combination's parts are checked on their own (goalParts lists them).
    case 'all':
    case 'any':
    case 'quiz':
    case 'estimate':
    case 'picture':
    case 'challenge':
    case 'code':
    case 'info':
      return [];
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/**
 * The state a level starts in, with the parts that start empty filled in (something
 * selected, a pixel selected) so that paths into them can be checked too.
 */
function sampleState(scene: Scene): LabState {
  return { ...initialState(scene), selection: { kind: 'object', id: '' }, selectedPixel: [0, 0] };
}

function pathProblem(path: string, sample: LabState, at: (string | number)[]): Problem[] {
  const problem = problemWithPath(path, sample);
  return problem ? [{ path: at, reason: problem }] : [];
}

/** A guide must ring something the learner can see in this level. */
function guideProblems(level: Level, target: GuideTarget): Reason[] {
  const { panel, control, item } = partsOfTarget(target);
  const shown = (ALWAYS_SHOWN as readonly string[]).includes(panel) || level.ui.panels.some((listed) => listed === panel);
  if (!shown) return [{ code: 'panelNotShown', target, panel }];
  const narrowed: Partial<Record<string, string[]>> = level.ui.controls ?? {};
  const only = narrowed[panel];
  if (only && !only.includes(control)) return [{ code: 'controlHidden', target, panel }];
  if (item === undefined) return [];
  if (control === 'pixel') return pixelProblems(level.scene, item);
  const ids = [...level.scene.objects, ...level.scene.lights].map((thing) => thing.id);
  return ids.includes(item) ? [] : [{ code: 'noSuchItem', item, ids }];
}

function pixelProblems(scene: Scene, item: string): Reason[] {
  const [columns, rows] = scene.camera.pixels;
  const match = /^(\d+),(\d+)$/.exec(item);
  if (match && Number(match[1]) < columns && Number(match[2]) < rows) return [];
  return [{ code: 'pixelOffScreen', item, columns, rows }];
}

/**
 * A task that asks for one pixel rings that very pixel (for "any pixel", the whole screen
 * will do), and a level whose tasks pick pixels shows the flat pixel preview: in the 3D view
 * a screen cell is a few pixels wide, too small to hit by counting (issue 9).
 */
function pixelPickingProblems(level: Level): Problem[] {
  const problems: Problem[] = [];
  level.tasks.forEach((task, index) => {
    const goal = task.goal;
    const pixel = goal.kind === 'event' && goal.event === 'pixel.selected' ? goal.with?.pixel : undefined;
    if (!Array.isArray(pixel)) return;
    const target = `screen.pixel:${pixel[0]},${pixel[1]}`;
    if (task.guide !== target) problems.push({ path: ['tasks', index, 'guide'], reason: { code: 'guideNotGoalPixel', target } });
  });
  const picksPixels = level.tasks.some((task) => task.solution?.some((action) => action.type === 'pixel.selected'));
  if (picksPixels && !level.ui.panels.includes('screen-preview')) {
    problems.push({ path: ['ui', 'panels'], reason: { code: 'previewRequired' } });
  }
  return problems;
}

/**
 * A view frames things the scene has (or a pixel's rays, "rays:3,1", of a pixel the screen
 * has), chooses a pixel its screen has, and frames the chosen pixel's rays ("pixel-rays")
 * only together with the pixel it chooses (an earlier task's pick may have been undone).
 */
function viewProblems(scene: Scene, view: DeclaredView, at: (string | number)[]): Problem[] {
  const problems: Problem[] = [];
  const names = [...FRAMED_PARTS, ...scene.objects.map((thing) => thing.id), ...scene.lights.map((thing) => thing.id)];
  (view.frame ?? []).forEach((name, index) => {
    const raysOf = framedRaysPixel(name);
    if (raysOf) {
      for (const reason of pixelProblems(scene, raysOf.join(','))) problems.push({ path: [...at, 'frame', index], reason });
    } else if (!names.includes(name)) {
      problems.push({ path: [...at, 'frame', index], reason: { code: 'notAllowed', allowed: [...names, 'rays:<column>,<row>'], got: gotOf(name) } });
    }
  });
  if (view.pixel) {
    for (const reason of pixelProblems(scene, view.pixel.join(','))) problems.push({ path: [...at, 'pixel'], reason });
  }
  if (view.frame?.includes('pixel-rays') && !view.pixel) {
    problems.push({ path: [...at, 'frame'], reason: { code: 'pixelRaysWithoutPixel' } });
  }
  return problems;
}

/** `ui.movable` names things the starting scene has, or its camera. */
function movableProblems(level: Level): Problem[] {
  const names = [...level.scene.objects.map((thing) => thing.id), ...level.scene.lights.map((thing) => thing.id), MOVABLE_CAMERA];
  return (level.ui.movable ?? []).flatMap((name, index) =>
    names.includes(name) ? [] : [{ path: ['ui', 'movable', index], reason: { code: 'notAllowed', allowed: names, got: gotOf(name) } }],
  );
}

/** "Show me" does what the learner could: a solution moves, turns, scales or deletes no item `ui.movable` locks. */
function lockedBySolutionProblems(level: Level): Problem[] {
  return level.tasks.flatMap((task, taskIndex) =>
    (task.solution ?? []).flatMap((action, index) => {
      const locked = lockedItemMoved(action, level.ui.movable);
      return locked === null ? [] : [{ path: ['tasks', taskIndex, 'solution', index], reason: { code: 'lockedItemMoved', item: locked } }];
    }),
  );
}

/** Evidence names things the scene has, and a pixel its screen has. */
function evidenceProblems(scene: Scene, evidence: TaskEvidence, at: (string | number)[]): Problem[] {
  const ids = [...scene.objects, ...scene.lights].map((thing) => thing.id);
  const problems: Problem[] = (evidence.objects ?? []).flatMap((id, index) =>
    ids.includes(id) ? [] : [{ path: [...at, 'objects', index], reason: { code: 'noSuchItem', item: id, ids } }],
  );
  if (evidence.rays) {
    for (const reason of pixelProblems(scene, evidence.rays.pixel.join(','))) problems.push({ path: [...at, 'rays', 'pixel'], reason });
  }
  return problems;
}

function badgeProblems(level: Level): Problem[] {
  const taskIds = level.tasks.map((task) => task.id);
  return level.badges.flatMap((badge, badgeIndex) =>
    badge.tasks.flatMap((taskId, index) =>
      taskIds.includes(taskId) ? [] : [{ path: ['badges', badgeIndex, 'tasks', index], reason: { code: 'noSuchTask', id: taskId } }],
    ),
  );
}
