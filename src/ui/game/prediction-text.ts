import { msg, str } from '@lit/localize';
import type { Prediction } from '../../quest/goal-check.ts';
import { predictionParts, type PredictionGoal } from '../../quest/goal.ts';
import type { Locale } from '../../quest/localized-text.ts';
import { plainLevelText } from '../../quest/text-markup.ts';
import { localNumbers } from '../../i18n/number-format.ts';

/** Numbers as the learner's language writes them, with as many decimals as they typed (up to 6). */
const numbers = localNumbers({ maximumFractionDigits: 6 });

/** Units written against the number, as the SI brochure (§5.4.3) writes angles: 41.8°, not 41.8 °. */
const UNITS_WITHOUT_SPACE = new Set(['°', '′', '″']);

function withUnit(goal: PredictionGoal, value: number, locale: Locale): string {
  const unit = goal.kind === 'estimate' && goal.estimate.unit ? plainLevelText(goal.estimate.unit, locale) : '';
  const gap = unit === '' || UNITS_WITHOUT_SPACE.has(unit) ? '' : ' ';
  return `${numbers.format(value)}${gap}${unit}`;
}

/**
 * A choice's words: a quiz's text, or for a picture "picture B", lettered by where this
 * learner sees it (`order`: file positions in the order shown).
 */
export function choiceLabel(goal: PredictionGoal, index: number, order: readonly number[], locale: Locale): string {
  if (goal.kind === 'quiz') return plainLevelText(goal.quiz.choices[index] ?? '', locale);
  const letter = String.fromCharCode(65 + Math.max(0, order.indexOf(index)));
  return msg(str`picture ${letter}`);
}

/** A prediction in words: the chosen choice, or the number with its unit. */
export function predictionText(goal: PredictionGoal, prediction: Prediction, locale: Locale, order: readonly number[]): string {
  if ('value' in prediction) return withUnit(goal, prediction.value, locale);
  return choiceLabel(goal, prediction.choice, order, locale);
}

/** The right answer in words; a number with its tolerance ("5 ± 0.5 m"). */
export function answerText(goal: PredictionGoal, locale: Locale, order: readonly number[]): string {
  if (goal.kind !== 'estimate') return choiceLabel(goal, predictionParts(goal).answer, order, locale);
  const { answer, tolerance } = goal.estimate;
  return tolerance > 0 ? `${numbers.format(answer)} ± ${withUnit(goal, tolerance, locale)}` : withUnit(goal, answer, locale);
}
