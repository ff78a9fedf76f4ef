/**
 * Where the task column scrolls when the quest panel shows something new (issue 37: "the
 * level's text is where the eye is"). A level that opens opens at its title and intro, not
 * where the last level's column was scrolled to; within a level, the current task (or a
 * prediction being revealed) is brought into view when it changes, since the tasks done
 * above it push it down.
 */

/** What the task column shows: the level's id and the task it holds open, or null. */
export interface TaskFocus {
  level: string | null;
  task: string | null;
}

export type TaskScroll = { kind: 'top' } | { kind: 'task'; task: string } | { kind: 'stay' };

/** The scroll that goes with a change from `before` to `now`. */
export function taskScroll(before: TaskFocus, now: TaskFocus): TaskScroll {
  if (now.level !== null && now.level !== before.level) return { kind: 'top' };
  if (now.task !== null && now.task !== before.task) return { kind: 'task', task: now.task };
  return { kind: 'stay' };
}
