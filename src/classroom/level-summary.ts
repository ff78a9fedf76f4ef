import type { Goal } from '../quest/goal.ts';
import type { Level } from '../quest/level-schema.ts';

/**
 * What a level asks of a pupil, for the teacher page's level list: how many tasks of each
 * kind, and a stated estimate of the minutes its required tasks take.
 *
 * The minutes are an estimate from the tasks, not a measurement: no class's times are known
 * to the teacher page yet. Each task kind counts a fixed time (MINUTES_PER_TASK), the level's
 * introduction one minute, and the sum is rounded up to a half minute. docs/classroom.md
 * gives the figures; the dashboard's median active times are the real ones once a class
 * has played.
 */

/**
 * The kinds of task in a teacher's words: do something in the lab, match a target picture (a
 * challenge), write a function (a code lab), answer a choice question, choose a picture,
 * estimate a number, read a text.
 */
export const TEACHER_TASK_KINDS = ['action', 'challenge', 'code', 'question', 'picture', 'estimate', 'read'] as const;
export type TeacherTaskKind = (typeof TEACHER_TASK_KINDS)[number];

/**
 * Minutes a task of each kind is counted for: a text to read half a minute; a question or a
 * picture to choose one minute (read, think, answer, read the explanation); a number to
 * estimate, or an action in the lab (find the control, do it, look at the result), a minute
 * and a half; a challenge four (study the target, change, render and compare three or four
 * times: its par); a code lab eight (read the contract, write, run the tests a few times).
 */
export const MINUTES_PER_TASK: Readonly<Record<TeacherTaskKind, number>> = {
  read: 0.5,
  question: 1,
  picture: 1,
  estimate: 1.5,
  action: 1.5,
  challenge: 4,
  code: 8,
};
/** Reading a level's introduction. */
export const INTRO_MINUTES = 1;

export function teacherTaskKind(goal: Goal): TeacherTaskKind {
  switch (goal.kind) {
    case 'info':
      return 'read';
    case 'quiz':
      return 'question';
    case 'picture':
      return 'picture';
    case 'estimate':
      return 'estimate';
    case 'event':
    case 'state':
    case 'all':
    case 'any':
      return 'action';
    case 'challenge':
      return 'challenge';
    case 'code':
      return 'code';
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/** How many of the level's tasks (or of `taskIds` among them) are of each kind, the kinds it has in TEACHER_TASK_KINDS order. */
export function taskKindCounts(level: Level, taskIds?: readonly string[]): { kind: TeacherTaskKind; count: number }[] {
  const tasks = taskIds ? level.tasks.filter((task) => taskIds.includes(task.id)) : level.tasks;
  return TEACHER_TASK_KINDS.map((kind) => ({ kind, count: tasks.filter((task) => teacherTaskKind(task.goal) === kind).length })).filter(
    ({ count }) => count > 0,
  );
}

/** The stated estimate of a level's minutes with `required` as its required tasks: its introduction and those tasks, rounded up to a half minute. */
export function estimatedMinutes(level: Level, required: readonly string[]): number {
  const tasks = level.tasks.filter((task) => required.includes(task.id));
  const minutes = INTRO_MINUTES + tasks.reduce((sum, task) => sum + MINUTES_PER_TASK[teacherTaskKind(task.goal)], 0);
  return Math.ceil(minutes * 2) / 2;
}
