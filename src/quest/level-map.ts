import type { Issue } from '../util/issue.ts';
import { isPassed, requiredTaskIds, type RequiredTasks } from './level-gate.ts';
import { playableLevels, type LevelCatalog } from './level-index.ts';
import type { Level } from './level-schema.ts';
import type { LocalizedText } from './localized-text.ts';
import type { LevelProgress } from './progress.ts';
import type { Stars } from './challenge-par.ts';

/**
 * The level map: chapters, and for each level its lock, tick, points and a challenge's stars. A level opens when
 * every playable level before it is passed (the gate); broken levels are listed with their
 * reasons and passed over, so one bad file does not lock the rest of the game.
 */

export type LevelStatus = 'locked' | 'open' | 'passed' | 'broken';

export interface LevelMapEntry {
  id: string;
  status: LevelStatus;
  /** Why a broken level is broken. */
  errors: Issue[];
  /** The level, unless it is broken. */
  level?: Level;
  points: number;
  maxPoints: number;
  /** The golf score of the level's challenge, once the learner matched it (the first challenge task's saved stars). */
  stars?: Stars;
}

export interface ChapterMapView {
  id: string;
  title: LocalizedText;
  levels: LevelMapEntry[];
}

type ProgressByLevel = Readonly<Record<string, LevelProgress>>;

export function statusOfLevel(catalog: LevelCatalog, progress: ProgressByLevel, assignment: RequiredTasks | undefined, id: string): LevelStatus {
  const levels = playableLevels(catalog);
  const position = levels.findIndex((level) => level.id === id);
  if (position < 0) return 'broken';
  const passed = (level: Level) => isPassed(level, progress[level.id], requiredTaskIds(level, assignment));
  if (passed(levels[position])) return 'passed';
  return levels.slice(0, position).every(passed) ? 'open' : 'locked';
}

export function levelMap(catalog: LevelCatalog, progress: ProgressByLevel, assignment: RequiredTasks | undefined): ChapterMapView[] {
  return catalog.chapters.map((chapter) => ({
    id: chapter.id,
    title: chapter.title,
    levels: chapter.entries.map((entry): LevelMapEntry => {
      if (!entry.ok) return { id: entry.id, status: 'broken', errors: entry.errors, points: 0, maxPoints: 0 };
      const done = Object.values(progress[entry.id]?.tasks ?? {});
      return {
        id: entry.id,
        status: statusOfLevel(catalog, progress, assignment, entry.id),
        errors: [],
        level: entry.level,
        points: done.reduce((sum, task) => sum + task.points, 0),
        maxPoints: entry.level.tasks.reduce((sum, task) => sum + task.points, 0),
        ...starsOf(entry.level, progress[entry.id]),
      };
    }),
  }));
}

function starsOf(level: Level, record: LevelProgress | undefined): { stars?: Stars } {
  const challenge = level.tasks.find((task) => task.goal.kind === 'challenge');
  const stars = challenge && record?.tasks[challenge.id]?.stars;
  return stars === undefined ? {} : { stars };
}
