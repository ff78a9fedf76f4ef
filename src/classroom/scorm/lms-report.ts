import type { LoggedEvent } from '../../quest/event-log.ts';
import { kindOfGoal, type TaskKind } from '../../quest/goal.ts';
import { isPassed, requiredTaskIds, type RequiredTasks } from '../../quest/level-gate.ts';
import type { Level } from '../../quest/level-schema.ts';
import type { Progress } from '../../quest/progress.ts';
import { isoAt } from '../iso-duration.ts';
import { optionId } from '../quiz-options.ts';

/**
 * What the game tells the learning platform, read from the learner's progress: whether the
 * assignment is done, its score and one interaction per task and quiz. Pure, so that the
 * same progress always gives the same report (the bridge sends only what changed).
 *
 * - Completion: every level of the assignment passed (all its required tasks done).
 * - Score: the points of the required tasks (the teacher's choice, else the level's
 *   mandatory ones), raw out of their maximum, as the issue asks: optional tasks do not
 *   count, so two pupils who did what was asked score the same.
 * - Interactions: one per task the learner did (required, or optional and touched), with
 *   its id `level/task`. A quiz (a prediction) is its first answer: the prediction before the
 *   result was seen, which is what a teacher wants to know; a second try after a wrong answer
 *   stays in the game's own exports. Information steps are read, not done: no interaction.
 *   An untouched optional task has none either (issue 40: no untouched task in any export).
 */

export type InteractionResult = 'correct' | 'incorrect' | 'neutral';

export interface LmsInteraction {
  /** `level/task`. */
  id: string;
  /** `choice`: a quiz answered with one of its choices; `numeric`: an estimate; `other`: a task done in the lab. */
  type: 'choice' | 'numeric' | 'other';
  /** The choice's option id (`a`, `b`, … by its place in the level file, as the exports' `quiz_choice`), the estimate's number, or how the task was completed (done, shown, skipped). */
  response: string;
  /** A task done by the learner is correct, one shown by "show me" or skipped is neutral; a quiz is right or wrong. */
  result: InteractionResult;
  /** ISO 8601: when the task began for the learner. */
  timestamp: string;
  /** From the task's start to the answer or completion. */
  latencyMs: number;
}

export interface LmsReport {
  completed: boolean;
  score: { raw: number; max: number };
  interactions: LmsInteraction[];
}

/** The assignment's levels as the game has them, and its required tasks (undefined: the levels' mandatory ones). */
export interface ReportScope {
  levels: readonly Level[];
  requiredTasks: RequiredTasks | undefined;
}

export function lmsReport(progress: Progress, scope: ReportScope): LmsReport {
  let raw = 0;
  let max = 0;
  for (const level of scope.levels) {
    const required = requiredTaskIds(level, scope.requiredTasks);
    const record = progress.levels[level.id];
    for (const task of level.tasks) {
      if (!required.has(task.id)) continue;
      max += task.points;
      raw += record?.tasks[task.id]?.points ?? 0;
    }
  }
  const completed =
    scope.levels.length > 0 && scope.levels.every((level) => isPassed(level, progress.levels[level.id], requiredTaskIds(level, scope.requiredTasks)));
  return { completed, score: { raw, max }, interactions: interactionsOf(progress, scope.levels) };
}

const key = (level: string, task: string) => `${level}/${task}`;

function interactionsOf(progress: Progress, levels: readonly Level[]): LmsInteraction[] {
  const kinds = new Map<string, TaskKind>(levels.flatMap((level) => level.tasks.map((task) => [key(level.id, task.id), kindOfGoal(task.goal)] as const)));
  const { startedAt, events } = progress.log;
  // When each task began: shown as the one to do (a required task), or first touched (an optional one).
  const began = new Map<string, number>();
  const found = new Map<string, LmsInteraction>();
  const interaction = (event: LoggedEvent & { level: string; task: string }, fields: Pick<LmsInteraction, 'type' | 'response' | 'result'>) => {
    const id = key(event.level, event.task);
    const from = began.get(id) ?? event.t;
    found.set(id, { id, ...fields, timestamp: isoAt(startedAt, from), latencyMs: event.t - from });
  };
  for (const event of events) {
    if (event.type === 'level.closed') {
      // Leaving a level ends its unfinished tasks: a later visit starts them again.
      for (const id of [...began.keys()]) if (id.startsWith(`${event.level}/`) && !found.has(id)) began.delete(id);
      continue;
    }
    if (event.type !== 'task.shown' && event.type !== 'task.started' && event.type !== 'quiz.answered' && event.type !== 'task.completed') continue;
    const id = key(event.level, event.task);
    const kind = kinds.get(id);
    if (kind === undefined || kind === 'info' || found.has(id)) continue;
    if (event.type === 'task.shown') {
      if (event.required) began.set(id, began.get(id) ?? event.t);
    } else if (event.type === 'task.started') {
      began.set(id, began.get(id) ?? event.t);
    } else if (event.type === 'quiz.answered') {
      const result = event.correct ? 'correct' : 'incorrect';
      if (event.choice !== undefined) interaction(event, { type: 'choice', response: optionId(event.choice), result });
      else interaction(event, { type: 'numeric', response: String(event.value ?? ''), result });
    } else {
      // A quiz completed without an answer was revealed by "show me".
      interaction(event, { type: 'other', response: event.how, result: event.how === 'done' ? 'correct' : 'neutral' });
    }
  }
  return [...found.values()];
}
