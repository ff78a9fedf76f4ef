import type { LevelPreset } from '../quest/level-index.ts';
import type { Level } from '../quest/level-schema.ts';
import type { Assignment } from './assignment.ts';

/**
 * The teacher page's one-click presets (levels/index.json `presets`): the assignment's
 * levels become the preset's, in its order, each requiring the level's own mandatory tasks
 * (what the teacher page gives a level added by hand). Everything else (title, language,
 * survey…) stays as the teacher set it. A level this version of the game cannot play is
 * left out rather than put in an assignment no student could finish.
 */
export function withPreset(assignment: Assignment, preset: LevelPreset, levels: readonly Level[]): Assignment {
  const chosen = preset.levels.flatMap((id) => levels.filter((level) => level.id === id));
  return {
    ...assignment,
    levels: chosen.map((level) => level.id),
    requiredTasks: Object.fromEntries(chosen.map((level) => [level.id, mandatoryTasks(level)])),
  };
}

/** A level's own mandatory tasks: what an assignment requires of it unless the teacher chooses others. */
export function mandatoryTasks(level: Level): string[] {
  return level.tasks.filter((task) => task.mandatory).map((task) => task.id);
}
