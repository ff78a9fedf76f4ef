import { msg, str } from '@lit/localize';
import { predictionOf } from '../../quest/goal.ts';
import type { Locale } from '../../quest/localized-text.ts';
import type { TaskView } from '../../quest/level-view.ts';
import { answerText, predictionText } from './prediction-text.ts';

/**
 * The line a prediction folds to once the learner has read its explanation and moved on
 * (issue 37: an answered quiz stayed open and pushed the next task below the column's edge):
 * what they expected and, when that was wrong, the answer; after "Show me", the answer. The
 * card shows this line under its title and opens again on a click. Null for a task that does
 * not fold: no prediction, or one not yet explained (still to answer, waiting for its
 * observation, or being explained now).
 */
export function foldedPrediction(view: TaskView, locale: Locale): string | null {
  const goal = predictionOf(view.task.goal);
  const prediction = view.prediction;
  if (!goal || !prediction || prediction.stage !== 'explained') return null;
  if (view.status === 'shown') return msg(str`The answer: “${answerText(goal, locale, prediction.order)}”`);
  if (view.status !== 'done' || !prediction.prediction) return null;
  const said = predictionText(goal, prediction.prediction, locale, prediction.order);
  return view.correct
    ? `✓ ${msg(str`You expected “${said}”, and so it is.`)}`
    : msg(str`You expected “${said}”; the answer is “${answerText(goal, locale, prediction.order)}”.`);
}
