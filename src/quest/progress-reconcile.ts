import type { Level } from './level-schema.ts';
import { TASK_POINTS } from './level-schema.ts';
import type { LevelProgress, TaskRecord } from './progress.ts';
import { pointsFor } from './scoring.ts';

/**
 * Saved progress is not trusted for points (a hand-edited save once showed "1e+308 of 85
 * points"): each completed task's points are worked out again from its level file, from how
 * it was completed. A task or level the game no longer has keeps its record, with points
 * no more than any task can give, so that a level that comes back later still counts.
 */
export function reconcileLevels(levels: Record<string, LevelProgress>, known: readonly Level[]): Record<string, LevelProgress> {
  const byId = new Map(known.map((level) => [level.id, level]));
  const reconciled: Record<string, LevelProgress> = {};
  for (const [id, record] of Object.entries(levels)) {
    const level = byId.get(id);
    const tasks: Record<string, TaskRecord> = {};
    for (const [taskId, task] of Object.entries(record.tasks)) {
      const fromFile = level?.tasks.find((candidate) => candidate.id === taskId);
      const points = fromFile ? pointsFor(fromFile, task.how, task.correct, task.stars) : Math.min(task.points, TASK_POINTS[1]);
      tasks[taskId] = points === task.points ? task : { ...task, points };
    }
    reconciled[id] = { ...record, tasks };
  }
  return reconciled;
}
