import { describe, expect, it } from 'vitest';
import { AnsweredQuiz } from '../../../src/ui/game/answered-quiz.ts';

describe('the answered quiz kept open in the task list', () => {
  it('stays open while it is current and while the task after it is, then folds up', () => {
    const quiz = new AnsweredQuiz();
    expect(quiz.openFor('predict')).toBeNull();
    quiz.answered('predict');
    // A wrong answer: the quiz is still the current task.
    expect(quiz.openFor('predict')).toBe('predict');
    // Answered right: the next task is current, the feedback still shows.
    expect(quiz.openFor('switch-on')).toBe('predict');
    expect(quiz.openFor('switch-on')).toBe('predict');
    // That task done too: the quiz folds up and stays folded.
    expect(quiz.openFor('render')).toBeNull();
    expect(quiz.openFor('switch-on')).toBeNull();
  });

  it('a quiz that ends the level stays open; another level or a newer answer replaces it', () => {
    const quiz = new AnsweredQuiz();
    quiz.answered('last-quiz');
    expect(quiz.openFor(null)).toBe('last-quiz');
    expect(quiz.openFor(null)).toBe('last-quiz');
    quiz.answered('optional-quiz');
    expect(quiz.openFor(null)).toBe('optional-quiz');
    quiz.clear();
    expect(quiz.openFor(null)).toBeNull();
  });
});
