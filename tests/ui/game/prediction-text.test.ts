import { describe, expect, it } from 'vitest';
import { goalSchema, type PredictionGoal } from '../../../src/quest/goal.ts';
import { answerText, predictionText } from '../../../src/ui/game/prediction-text.ts';

function estimate(unit: string | undefined, answer = 41.8, tolerance = 1.5): PredictionGoal {
  return goalSchema.parse({ estimate: { question: 'How large?', answer, tolerance, ...(unit === undefined ? {} : { unit }) } }) as PredictionGoal;
}

describe('a number prediction in words', () => {
  it('writes an angle against its number and other units after a space', () => {
    expect(predictionText(estimate('°'), { value: 40 }, 'en', [])).toBe('40°');
    expect(predictionText(estimate('m'), { value: 4.2 }, 'en', [])).toBe('4.2 m');
    expect(predictionText(estimate(undefined), { value: 7 }, 'en', [])).toBe('7');
  });

  it('gives the answer with its tolerance in the same form', () => {
    expect(answerText(estimate('°'), 'en', [])).toBe('41.8 ± 1.5°');
    expect(answerText(estimate('m', 4, 0), 'en', [])).toBe('4 m');
  });
});
