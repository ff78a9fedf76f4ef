// The line an explained prediction folds to (issue 37: "an answered quiz stays open and
// pushes the next task below the fold"): what the learner expected and the answer.
import { describe, expect, it } from 'vitest';
import type { PredictionView, TaskView } from '../../../src/quest/level-view.ts';
import { goalSchema } from '../../../src/quest/goal.ts';
import type { Task } from '../../../src/quest/level-schema.ts';
import { foldedPrediction } from '../../../src/ui/game/prediction-summary.ts';

const quizTask = {
  id: 'predict-no-shadows',
  title: 'Predict: Shadows off',
  text: 'Predict first.',
  mandatory: true,
  points: 10,
  hints: [],
  goal: goalSchema.parse({
    quiz: {
      question: 'What becomes of the grey shadow ray?',
      choices: ['It stays grey', 'It is not traced', 'It turns yellow'],
      answer: 1,
      explanation: 'Nothing tests the way.',
    },
  }),
} as unknown as Task;

const estimateTask = {
  ...quizTask,
  id: 'predict-critical-angle',
  goal: goalSchema.parse({ estimate: { question: 'How big is θc?', answer: 41.8, tolerance: 1, unit: '°', explanation: 'sin θc = 1/η.' } }),
} as unknown as Task;

function view(task: Task, status: TaskView['status'], prediction: Partial<PredictionView>, correct?: boolean): TaskView {
  return {
    task,
    kind: 'quiz',
    required: true,
    status,
    points: 0,
    correct,
    prediction: { stage: 'explained', order: [2, 0, 1], ...prediction },
    hints: [],
    nextHint: null,
    hintOffered: false,
  };
}

describe('an explained prediction folds to one line', () => {
  it('says a right prediction was right', () => {
    expect(foldedPrediction(view(quizTask, 'done', { prediction: { choice: 1 } }, true), 'en')).toBe('✓ You expected “It is not traced”, and so it is.');
  });

  it('gives the answer beside a wrong prediction, a number with its tolerance and unit', () => {
    expect(foldedPrediction(view(quizTask, 'done', { prediction: { choice: 0 } }, false), 'en')).toBe(
      'You expected “It stays grey”; the answer is “It is not traced”.',
    );
    expect(foldedPrediction(view(estimateTask, 'done', { order: [], prediction: { value: 30 } }, false), 'en')).toBe(
      'You expected “30°”; the answer is “41.8 ± 1°”.',
    );
  });

  it('gives the answer after "Show me"', () => {
    expect(foldedPrediction(view(quizTask, 'shown', {}), 'en')).toBe('The answer: “It is not traced”');
  });

  it('does not fold a prediction still to make, waiting for its observation, or being explained now', () => {
    for (const stage of ['ask', 'wait', 'reflect', 'explain'] as const) {
      expect(foldedPrediction(view(quizTask, stage === 'ask' ? 'current' : 'done', { stage, prediction: { choice: 0 } }, false), 'en'), stage).toBeNull();
    }
  });

  it('does not fold a task that is no prediction', () => {
    const selectPixel = { ...quizTask, id: 'select-pixel', goal: goalSchema.parse({ event: 'pixel.selected' }) } as unknown as Task;
    expect(foldedPrediction({ ...view(selectPixel, 'done', {}), kind: 'do', prediction: undefined }, 'en')).toBeNull();
  });
});
