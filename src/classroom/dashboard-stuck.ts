import { quantile } from './dashboard-stats.ts';
import type { TaskSummary } from './dashboard-summary.ts';

/**
 * Sticking points: the tasks of a level where clearly more learners needed help than on
 * the level's other tasks. "Needing help" is a hint opened, "show me", or not finishing a
 * mandatory task (dashboard-summary.ts); a hint offered after idle time counts only once
 * opened. In a typical class most tasks see some hints, so a fixed share alone flags too
 * many tasks; an outlier
 * is a task whose share is both high and well above what is usual in its level:
 *
 *   share ≥ STUCK_MIN_SHARE  and  share ≥ STUCK_TIMES_TYPICAL × (median share of the level's mandatory tasks)
 *
 * Only mandatory tasks count (an optional task nobody needs is not a point to get stuck
 * at), and only with at least STUCK_MIN_LEARNERS learners (fewer is anecdote, not a pattern).
 */
export const STUCK_MIN_SHARE = 0.4;
export const STUCK_TIMES_TYPICAL = 2;
export const STUCK_MIN_LEARNERS = 3;

export function helpShare(task: Pick<TaskSummary, 'learners' | 'learnersNeedingHelp'>): number {
  return task.learners === 0 ? 0 : task.learnersNeedingHelp / task.learners;
}

/** The ids of the level's tasks that are sticking points. */
export function stickingPoints(tasks: readonly TaskSummary[]): Set<string> {
  const counted = tasks.filter((task) => task.mandatory && task.learners >= STUCK_MIN_LEARNERS);
  const typical = quantile(
    counted.map(helpShare).sort((a, b) => a - b),
    0.5,
  );
  return new Set(counted.filter((task) => helpShare(task) >= STUCK_MIN_SHARE && helpShare(task) >= STUCK_TIMES_TYPICAL * typical).map((task) => task.task));
}
