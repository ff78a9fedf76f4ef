import type { LoggedEvent } from './event-log.ts';
import type { Prediction } from './goal-check.ts';
import { kindOfGoal, predictionOf } from './goal.ts';
import { isCompleted } from './level-gate.ts';
import type { Level, Task } from './level-schema.ts';
import type { LevelProgress } from './progress.ts';

/**
 * Where a prediction is (predict → observe → explain, White & Gunstone 1992): `ask` before
 * the learner predicts; `wait` while they do the task that shows the result (its observer);
 * then, once it is done, `reflect` (a wrong prediction: "you expected X, what do you see?")
 * and `explain` (the answer and why, until the learner moves on); `explained` after.
 * Pure rules over the level, its progress and the open reveal; the quest engine holds the state.
 */
export type PredictionStage = 'ask' | 'wait' | 'reflect' | 'explain' | 'explained';

/** The prediction whose result was just observed, and what the learner said they saw. */
export interface Reveal {
  quiz: string;
  reflection?: Prediction;
}

/**
 * The task whose result checks the prediction `quiz`: the first task after it that is done
 * in the lab, required if the quiz is; none when nothing after it shows the result.
 */
export function observerOf(level: Level, required: ReadonlySet<string>, quiz: Task): Task | undefined {
  const after = level.tasks.slice(level.tasks.indexOf(quiz) + 1);
  const quizRequired = required.has(quiz.id);
  return after.find((task) => kindOfGoal(task.goal) === 'do' && (!quizRequired || required.has(task.id)));
}

/** The prediction whose result the completion of `task` lets the learner see, if any. */
export function predictionRevealedBy(level: Level, required: ReadonlySet<string>, record: LevelProgress | undefined, task: Task): Task | undefined {
  const predicted = (quiz: Task) => predictionOf(quiz.goal) !== undefined && record?.tasks[quiz.id]?.how === 'done';
  // A prediction nothing after it checks is explained as soon as it is made.
  if (predicted(task)) return observerOf(level, required, task) ? undefined : task;
  return level.tasks.find((quiz) => predicted(quiz) && observerOf(level, required, quiz) === task);
}

/** Where the prediction task `task` is in predict → observe → explain. */
export function stageOf(level: Level, required: ReadonlySet<string>, record: LevelProgress | undefined, reveal: Reveal | null, task: Task): PredictionStage {
  const done = record?.tasks[task.id];
  if (!done) return 'ask';
  if (reveal?.quiz === task.id) return done.correct === false && !reveal.reflection ? 'reflect' : 'explain';
  if (done.how !== 'done') return 'explained';
  const observer = observerOf(level, required, task);
  return observer && !isCompleted(record, observer.id) ? 'wait' : 'explained';
}

/** The learner's last prediction for a task, from the log. */
export function lastPrediction(events: readonly LoggedEvent[], levelId: string, taskId: string): Prediction | undefined {
  const answered = events.findLast((event) => event.type === 'quiz.answered' && event.level === levelId && event.task === taskId);
  if (answered?.type !== 'quiz.answered') return undefined;
  if (answered.choice !== undefined) return { choice: answered.choice };
  return answered.value === undefined ? undefined : { value: answered.value };
}
