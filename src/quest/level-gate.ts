import type { Level, Task } from './level-schema.ts';
import type { LevelProgress } from './progress.ts';

/**
 * Which tasks of a level must be done, which one is the learner's to do now, and whether
 * the level is passed (the gate: the next level opens when it is).
 *
 * Order: required tasks are done one after another, in the level's order; the current
 * task is the first required one not yet completed. Tasks that are not required (optional
 * ones) can be completed at any time while the level is open.
 */

/**
 * A teacher's assignment (spec/classroom.md): per level id, the ids of the tasks required to
 * pass it. A level it does not name requires its mandatory tasks.
 */
export type RequiredTasks = Readonly<Record<string, readonly string[]>>;

export function requiredTaskIds(level: Level, assignment: RequiredTasks | undefined): ReadonlySet<string> {
  const chosen = assignment?.[level.id];
  const ids = chosen ?? level.tasks.filter((task) => task.mandatory).map((task) => task.id);
  return new Set(ids.filter((id) => level.tasks.some((task) => task.id === id)));
}

export function isCompleted(record: LevelProgress | undefined, taskId: string): boolean {
  return record?.tasks[taskId] !== undefined;
}

/** The required task to do now, or undefined when all are done. */
export function currentTask(level: Level, record: LevelProgress | undefined, required: ReadonlySet<string>): Task | undefined {
  return level.tasks.find((task) => required.has(task.id) && !isCompleted(record, task.id));
}

export function isPassed(level: Level, record: LevelProgress | undefined, required: ReadonlySet<string>): boolean {
  return currentTask(level, record, required) === undefined;
}
