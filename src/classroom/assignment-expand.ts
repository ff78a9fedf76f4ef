import type { Level } from '../quest/level-schema.ts';
import type { Assignment } from './assignment.ts';
import { mandatoryTasks } from './assignment-preset.ts';

/**
 * The inverse of compactAssignment (assignment-compact.ts), for a link opened on the teacher
 * page: a level the link leaves out of `requiredTasks` requires its own mandatory tasks, and
 * the form shows them ticked.
 */
export function expandAssignment(assignment: Assignment, levels: readonly Level[]): Assignment {
  const requiredTasks = Object.fromEntries(
    assignment.levels.flatMap((id) => {
      const given = assignment.requiredTasks[id];
      const level = levels.find((candidate) => candidate.id === id);
      if (given) return [[id, given]];
      return level ? [[id, mandatoryTasks(level)]] : [];
    }),
  );
  return { ...assignment, requiredTasks };
}
