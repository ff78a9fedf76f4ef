import type { Scene } from '../scene/scene.ts';
import { stageInVisit, type ActiveLevel } from './active-level.ts';
import type { Stars } from './challenge-par.ts';
import { choiceOrder } from './choice-order.ts';
import type { HintStep, HowCompleted, LoggedEvent } from './event-log.ts';
import type { Prediction } from './goal-check.ts';
import { kindOfGoal, predictionOf, predictionParts, type PictureGoal, type TaskKind } from './goal.ts';
import { nextHintStep, NO_HINTS } from './hint-ladder.ts';
import type { GuideTarget } from './lab-controls.ts';
import { isCompleted, isPassed } from './level-gate.ts';
import type { Level, Task } from './level-schema.ts';
import type { LocalizedText } from './localized-text.ts';
import { lastPrediction, observerOf, type PredictionStage } from './prediction-stage.ts';
import type { LevelProgress } from './progress.ts';

/**
 * What the quest engine shows the task panel (quest-engine.ts): the open level and each of its
 * tasks as views, read from the visit (active-level.ts), the level's saved record and the log.
 */

/** A task's status: `current` is the required task to do now; `open` a task that is not
 * required and not done; `waiting` a required task after the current one. */
export type TaskStatus = 'current' | 'open' | 'waiting' | HowCompleted;

export interface PredictionView {
  stage: PredictionStage;
  /** A quiz's choices in the order this learner sees them (file positions); empty for a number. */
  order: number[];
  /** The learner's prediction, once made (from the log). */
  prediction?: Prediction;
  /** What a learner whose prediction was wrong said they saw. */
  reflection?: Prediction;
  /** The task whose result checks the prediction; none when the result is seen at once. */
  observer?: Task;
  /** A picture prediction's scenes to render, one per choice in file order. */
  pictures?: readonly Scene[];
}

export interface TaskView {
  task: Task;
  kind: TaskKind;
  required: boolean;
  status: TaskStatus;
  /** Points earned; 0 until completed. */
  points: number;
  /** For an answered quiz: whether the prediction was right. */
  correct?: boolean;
  /** For a challenge the learner matched: its golf score, as saved. */
  stars?: Stars;
  /** For a quiz or estimate: its stage, the order of its choices, the learner's prediction. */
  prediction?: PredictionView;
  /** For the task that checks a prediction, while it is to do: that prediction and its quiz. */
  checks?: { quiz: Task; prediction: Prediction; order: number[] };
  /** The text hints shown so far. */
  hints: LocalizedText[];
  /** What asking for help does next (`show-me`: offer the "Show me" button); null when nothing is left. */
  nextHint: HintStep | null;
  /** The app offered the next rung after idle time and the learner has not opened it yet. */
  hintOffered: boolean;
}

export interface LevelView {
  level: Level;
  tasks: TaskView[];
  /** The required task to do now; null once the level is passed, or while a prediction is revealed. */
  current: TaskView | null;
  /** The prediction being revealed after its observation (the learner continues from it), or null. */
  revealing: TaskView | null;
  /** The level opened with the scene the learner left it with, not its own (see openLevel). */
  sceneKept: boolean;
  passed: boolean;
  points: number;
  maxPoints: number;
  /** The control to ring: the guide of the last guidance shown, while its task is not done. */
  ring: GuideTarget | null;
}

/** What the views are read from, besides the visit. */
export interface ViewSources {
  /** The open level's saved record; undefined before its first task is done. */
  record: LevelProgress | undefined;
  /** The event log, where each prediction is kept. */
  events: readonly LoggedEvent[];
  /** When the log started: with the level and task, it seeds the order of a quiz's choices. */
  logStart: string;
  /** A picture prediction's scenes (the engine makes them once per level file). */
  pictures: (goal: PictureGoal) => readonly Scene[];
}

export function levelViewOf(sources: ViewSources, active: ActiveLevel): LevelView {
  const { level, required } = active;
  const tasks = level.tasks.map((task) => taskViewOf(sources, active, task));
  return {
    level,
    tasks,
    current: tasks.find((view) => view.status === 'current') ?? null,
    revealing: tasks.find((view) => view.task.id === active.reveal?.quiz) ?? null,
    sceneKept: active.sceneKept,
    passed: isPassed(level, sources.record, required),
    points: tasks.reduce((sum, view) => sum + view.points, 0),
    maxPoints: level.tasks.reduce((sum, task) => sum + task.points, 0),
    ring: active.ring?.target ?? null,
  };
}

export function taskViewOf(sources: ViewSources, active: ActiveLevel, task: Task): TaskView {
  const done = sources.record?.tasks[task.id];
  const required = active.required.has(task.id);
  const status: TaskStatus = done ? done.how : active.current?.id === task.id ? 'current' : required ? 'waiting' : 'open';
  const hints = active.hints.get(task.id) ?? NO_HINTS;
  const prediction = predictionViewOf(sources, active, task);
  const checks = checksOf(sources, active, task);
  return {
    task,
    kind: kindOfGoal(task.goal),
    required,
    status,
    // A prediction's points show once its result has been observed (quest-engine.ts `points`).
    points: prediction?.stage === 'wait' ? 0 : (done?.points ?? 0),
    ...(done?.correct === undefined ? {} : { correct: done.correct }),
    ...(done?.stars === undefined ? {} : { stars: done.stars }),
    ...(prediction ? { prediction } : {}),
    ...(checks ? { checks } : {}),
    hints: task.hints.slice(0, hints.texts),
    nextHint: done ? null : nextHintStep(task, hints),
    hintOffered: !done && active.offered.has(task.id),
  };
}

function predictionViewOf(sources: ViewSources, active: ActiveLevel, task: Task): PredictionView | undefined {
  const goal = predictionOf(task.goal);
  if (!goal) return undefined;
  const seed = `${sources.logStart}/${active.level.id}/${task.id}`;
  const prediction = lastPrediction(sources.events, active.level.id, task.id);
  const reflection = active.reveal?.quiz === task.id ? active.reveal.reflection : undefined;
  const observer = observerOf(active.level, active.required, task);
  const pictures = goal.kind === 'picture' ? sources.pictures(goal) : undefined;
  return {
    ...(pictures ? { pictures } : {}),
    stage: stageInVisit(active, sources.record, task),
    order: choiceOrder(predictionParts(goal).choices, seed),
    ...(prediction ? { prediction } : {}),
    ...(reflection ? { reflection } : {}),
    ...(observer ? { observer } : {}),
  };
}

/** For a task to do that checks a prediction still waiting for it: the quiz and the prediction. */
function checksOf(sources: ViewSources, active: ActiveLevel, task: Task): TaskView['checks'] {
  if (kindOfGoal(task.goal) !== 'do' || isCompleted(sources.record, task.id)) return undefined;
  const quiz = active.level.tasks.find(
    (candidate) =>
      predictionOf(candidate.goal) &&
      stageInVisit(active, sources.record, candidate) === 'wait' &&
      observerOf(active.level, active.required, candidate) === task,
  );
  const prediction = quiz && lastPrediction(sources.events, active.level.id, quiz.id);
  const order = quiz && predictionViewOf(sources, active, quiz)?.order;
  return quiz && prediction && order ? { quiz, prediction, order } : undefined;
}
