import type { Survey, SurveyQuestion } from './survey-schema.ts';

/**
 * A learner's answers to a survey and their checking. An answer is the chosen option's id
 * (choice), a number (scale, number) or text; a question left open has no entry.
 */

export type SurveyAnswers = Record<string, string | number>;

/** What is wrong with one answer; the UI words it (rt-survey.ts). */
export type AnswerProblem =
  | { kind: 'required' }
  | { kind: 'not-a-number' }
  | { kind: 'not-whole' }
  | { kind: 'out-of-range'; min: number | undefined; max: number | undefined }
  | { kind: 'too-long'; max: number }
  | { kind: 'unknown-option' };

/** The answers as they were handed in, with the survey's id: stored and exported. */
export interface SurveySubmission {
  survey: string;
  /** ISO 8601. */
  submittedAt: string;
  answers: SurveyAnswers;
}

/** The problem with each question's answer; an empty object when all can be handed in. */
export function checkAnswers(survey: Survey, answers: SurveyAnswers): Record<string, AnswerProblem> {
  const problems: Record<string, AnswerProblem> = {};
  for (const question of survey.questions) {
    const problem = checkAnswer(question, answers[question.id]);
    if (problem) problems[question.id] = problem;
  }
  return problems;
}

export function checkAnswer(question: SurveyQuestion, answer: string | number | undefined): AnswerProblem | null {
  const empty = answer === undefined || (typeof answer === 'string' && answer.trim() === '');
  if (empty) return question.required ? { kind: 'required' } : null;
  switch (question.type) {
    case 'choice':
      return question.options.some((option) => option.id === answer) ? null : { kind: 'unknown-option' };
    case 'text':
      return typeof answer === 'string' && answer.length <= question.maxLength ? null : { kind: 'too-long', max: question.maxLength };
    case 'scale':
    case 'number': {
      if (typeof answer !== 'number' || !Number.isFinite(answer)) return { kind: 'not-a-number' };
      const integer = question.type === 'scale' || question.integer;
      if (integer && !Number.isInteger(answer)) return { kind: 'not-whole' };
      const { min, max } = question;
      if ((min !== undefined && answer < min) || (max !== undefined && answer > max)) return { kind: 'out-of-range', min, max };
      return null;
    }
  }
}

/** Only the answers to the survey's own questions, text trimmed, empty ones left out. */
export function cleanAnswers(survey: Survey, answers: SurveyAnswers): SurveyAnswers {
  const clean: SurveyAnswers = {};
  for (const question of survey.questions) {
    const answer = answers[question.id];
    const value = typeof answer === 'string' ? answer.trim() : answer;
    if (value !== undefined && value !== '') clean[question.id] = value;
  }
  return clean;
}
