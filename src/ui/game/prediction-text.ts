import type { Prediction } from '../../quest/goal-check.ts';
import type { PredictionGoal } from '../../quest/goal.ts';
import { localize, type Locale } from '../../quest/localized-text.ts';
import { localNumbers } from '../../i18n/number-format.ts';

/** Numbers as the learner's language writes them, with as many decimals as they typed (up to 6). */
const numbers = localNumbers({ maximumFractionDigits: 6 });

function withUnit(goal: PredictionGoal, value: number, locale: Locale): string {
  const unit = 'estimate' in goal && goal.estimate.unit ? ` ${localize(goal.estimate.unit, locale)}` : '';
  return `${numbers.format(value)}${unit}`;
}

/** A prediction in words: the text of the chosen choice, or the number with its unit. */
export function predictionText(goal: PredictionGoal, prediction: Prediction, locale: Locale): string {
  if ('quiz' in goal) return 'choice' in prediction ? localize(goal.quiz.choices[prediction.choice] ?? '', locale) : '';
  return 'value' in prediction ? withUnit(goal, prediction.value, locale) : '';
}

/** The right answer in words; a number with its tolerance ("5 ± 0.5 m"). */
export function answerText(goal: PredictionGoal, locale: Locale): string {
  if ('quiz' in goal) return localize(goal.quiz.choices[goal.quiz.answer] ?? '', locale);
  const { answer, tolerance } = goal.estimate;
  return tolerance > 0 ? `${numbers.format(answer)} ± ${withUnit(goal, tolerance, locale)}` : withUnit(goal, answer, locale);
}
