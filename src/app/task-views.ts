import type { DeclaredView, LabAction } from '../lab-state/lab-action.ts';
import type { Level, Task } from '../quest/level-schema.ts';

type ViewApplied = Extract<LabAction, { type: 'view.applied' }>;

/**
 * When the declared views of a level (docs/levels.md, "Views") are applied: the level's own
 * when it opens, together with the view of the task it opens on; then each task's own when
 * it becomes the current one, once per visit (coming back to a task the learner left by
 * reloading applies it again, which is what they would expect: the task starts over).
 *
 * Only tasks that are current get their view: optional tasks are all on show at once, and
 * moving the view for one the learner did not ask about would pull it away from another.
 * The app dispatches the returned action; the quest engine never counts it (quest-engine.ts).
 */
export class TaskViews {
  /** The open level's id: until `opened` is told, the game's changes are the opening itself. */
  private level: string | null = null;
  /** The current task whose view was last applied (level id and task id), so it is applied once. */
  private applied: string | null = null;

  /** The view to apply as `level` opens on `current` (null: the level has none), as one action. */
  opened(level: Level, current: Task | null): ViewApplied | null {
    this.level = level.id;
    this.applied = current ? key(level, current) : null;
    const view = combineViews(level.view, current?.view);
    return view ? { type: 'view.applied', view } : null;
  }

  /** After any change of the game: the view of a task that has just become current, or null. */
  changed(level: Level | null, current: Task | null): ViewApplied | null {
    if (!level || !current || level.id !== this.level) return null;
    const now = key(level, current);
    if (now === this.applied) return null;
    this.applied = now;
    return current.view ? { type: 'view.applied', view: current.view } : null;
  }

  /** The level was left: the next one opens afresh. */
  closed(): void {
    this.level = null;
    this.applied = null;
  }
}

function key(level: Level, task: Task): string {
  return `${level.id}/${task.id}`;
}

/**
 * A task's view on top of its level's: its ray options over the level's, its pixel if it
 * chooses one, and its way of looking (frame or camera) instead of the level's when it has one.
 */
export function combineViews(level: DeclaredView | undefined, task: DeclaredView | undefined): DeclaredView | null {
  if (!level || !task) return level ?? task ?? null;
  const base: DeclaredView = { ...level };
  if (task.frame !== undefined || task.throughCamera !== undefined) {
    delete base.frame;
    delete base.from;
    delete base.throughCamera;
  }
  return {
    ...base,
    ...task,
    ...(level.rays || task.rays ? { rays: { ...level.rays, ...task.rays } } : {}),
  };
}
