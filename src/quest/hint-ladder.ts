import type { HintStep } from './event-log.ts';
import { kindOfGoal } from './goal.ts';
import type { Task } from './level-schema.ts';

/**
 * The hint ladder of a task (spec): first its text hints, one at a time; then guidance, a
 * pulsing ring on the task's `guide` control; last "show me", where the app performs the
 * task's solution (or reveals a quiz's answer) and the task counts as shown, not earned.
 * A rung the task has nothing for is passed over.
 */

/** How far up the ladder a task is. */
export interface HintProgress {
  /** How many text hints have been shown. */
  texts: number;
  /** Whether the guide control has been ringed. */
  guided: boolean;
}

export const NO_HINTS: HintProgress = { texts: 0, guided: false };

/** The rung that asking for help reaches next, or null when the ladder is used up. */
export function nextHintStep(task: Task, progress: HintProgress): HintStep | null {
  if (progress.texts < task.hints.length) return 'text';
  if (task.guide && !progress.guided) return 'guidance';
  return canShowMe(task) ? 'show-me' : null;
}

/** "Show me" needs something to show: the actions of a task's solution, or a quiz's answer. */
export function canShowMe(task: Task): boolean {
  const kind = kindOfGoal(task.goal);
  return kind === 'quiz' || (kind === 'do' && task.solution !== undefined);
}

/** The ladder after showing a text hint or the guidance. */
export function climb(progress: HintProgress, step: 'text' | 'guidance'): HintProgress {
  return step === 'text' ? { ...progress, texts: progress.texts + 1 } : { ...progress, guided: true };
}
