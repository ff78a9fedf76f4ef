import type { Badge } from './badges.ts';
import type { HowCompleted } from './event-log.ts';
import type { LabAction } from '../lab-state/lab-action.ts';
import { challengeStars, pointsForStars, type Stars } from './challenge-par.ts';
import { goalParts, kindOfGoal, type Goal } from './goal.ts';
import { isPassed } from './level-gate.ts';
import type { Level, Task } from './level-schema.ts';
import type { LevelProgress } from './progress.ts';

/**
 * Points for a completed task. A task completed by "show me" is shown, not earned: no
 * points (it still counts for the gate, so nobody is stuck). Text hints and guidance the
 * learner opens cost nothing but the level's no-hints badge (a hint offered after idle time
 * costs nothing until opened: quest-engine.ts). A wrong quiz prediction completes the task
 * without points: predicting is the exercise, checking in the scene the lesson. A matched
 * challenge earns its points by its stars (challenge-par.ts pointsForStars).
 */
export function pointsFor(task: Task, how: HowCompleted, correct?: boolean, stars?: Stars): number {
  if (how !== 'done') return 0;
  if (kindOfGoal(task.goal) === 'quiz' && correct === false) return 0;
  return stars === undefined ? task.points : pointsForStars(task.points, stars);
}

/**
 * The stars a challenge in `goal` earns when `action` (the referee's comparison, with its
 * counts) meets it; undefined for any other goal or action.
 */
export function starsEarned(goal: Goal, action: LabAction): Stars | undefined {
  if (action.type !== 'challenge.compared') return undefined;
  const challenge = goalParts(goal).find((part) => part.goal.kind === 'challenge')?.goal;
  return challenge?.kind === 'challenge' ? challengeStars(action, challenge.challenge.par) : undefined;
}

/** A task the learner did themself: not shown, not skipped, not a wrong prediction. */
function earnedByLearner(record: LevelProgress | undefined, taskId: string): boolean {
  const done = record?.tasks[taskId];
  return done?.how === 'done' && done.correct !== false;
}

/** The level's badges whose conditions hold now (the engine awards each once). */
export function levelBadgesEarned(level: Level, record: LevelProgress | undefined, required: ReadonlySet<string>): Badge[] {
  const badges: Badge[] = [];
  if (isPassed(level, record, required) && (record?.hintsUsed ?? 0) === 0) badges.push({ kind: 'no-hints', level: level.id });
  if (level.tasks.every((task) => record?.tasks[task.id]?.how === 'done')) badges.push({ kind: 'every-task', level: level.id });
  for (const badge of level.badges) {
    if (badge.tasks.every((taskId) => earnedByLearner(record, taskId))) badges.push({ kind: 'level-badge', level: level.id, badge: badge.id });
  }
  return badges;
}
