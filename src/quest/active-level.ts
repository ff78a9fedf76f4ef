import type { EventTally } from './goal-check.ts';
import type { HintProgress } from './hint-ladder.ts';
import { predictionOf } from './goal.ts';
import type { GuideTarget } from './lab-controls.ts';
import { isCompleted } from './level-gate.ts';
import type { Level, Task } from './level-schema.ts';
import { stageOf, type PredictionStage, type Reveal } from './prediction-stage.ts';
import type { LevelProgress } from './progress.ts';

/** The open level's state that lasts for this visit only (quest-engine.ts); what lasts is in its LevelProgress. */
export interface ActiveLevel {
  level: Level;
  required: ReadonlySet<string>;
  current: Task | undefined;
  /** Event goals matched since each watched task was shown. */
  tallies: Map<string, EventTally>;
  hints: Map<string, HintProgress>;
  /** Tasks whose first rung was offered after idle time (once per visit). */
  offered: Set<string>;
  /** Tasks whose "show me" was used: they complete as shown. */
  shownByApp: Set<string>;
  /** Optional tasks the learner has started on in this visit (`task.started` logged). */
  started: Set<string>;
  ring: { task: string; target: GuideTarget } | null;
  /** The prediction whose result was just observed: it holds the level until the learner continues. */
  reveal: Reveal | null;
  /** Opened with the scene the learner left, not the level's own. */
  sceneKept: boolean;
}

/** A visit that has just begun: no task current yet, nothing tallied, hinted, offered or started. */
export function newVisit(level: Level, required: ReadonlySet<string>, sceneKept: boolean): ActiveLevel {
  return {
    level,
    required,
    current: undefined,
    tallies: new Map(),
    hints: new Map(),
    offered: new Set(),
    shownByApp: new Set(),
    started: new Set(),
    ring: null,
    reveal: null,
    sceneKept,
  };
}

/** A prediction task's stage in this visit, given the level's saved record. */
export function stageInVisit(active: ActiveLevel, record: LevelProgress | undefined, task: Task): PredictionStage {
  return stageOf(active.level, active.required, record, active.reveal, task);
}

/** The task if the learner can work on it now: in the open level, not done, and either current or not required. */
export function workableTask(active: ActiveLevel, record: LevelProgress | undefined, taskId: string): Task | undefined {
  const task = active.level.tasks.find((candidate) => candidate.id === taskId);
  if (!task || isCompleted(record, taskId)) return undefined;
  if (active.required.has(taskId) && active.current?.id !== taskId) return undefined;
  return task;
}

/**
 * The points of the visit's predictions still waiting for their observation: they are left out
 * of the score shown, since a score that jumped at "lock in" would tell whether the prediction was right.
 */
export function pointsAwaitingObservation(active: ActiveLevel, record: LevelProgress | undefined): number {
  if (!record) return 0;
  const waiting = active.level.tasks.filter((task) => predictionOf(task.goal) && stageInVisit(active, record, task) === 'wait');
  return waiting.reduce((sum, task) => sum + (record.tasks[task.id]?.points ?? 0), 0);
}
