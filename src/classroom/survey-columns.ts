import type { SurveyAnswers } from './survey-answers.ts';
import type { Survey } from './survey-schema.ts';

export type SurveyLookup = (id: string) => Survey | undefined;

/**
 * The survey questions that get a CSV column, in the surveys' own order: every question of
 * each survey named (answered or only planned by the assignment), then answers to questions
 * the app does not know (a survey from another version), in the order they appear.
 */
export function surveyQuestionIds(
  surveyById: SurveyLookup,
  named: readonly (string | null | undefined)[],
  answered: readonly (SurveyAnswers | null | undefined)[],
): string[] {
  const ids = new Set<string>();
  for (const id of named) for (const question of (id && surveyById(id)?.questions) || []) ids.add(question.id);
  for (const answers of answered) for (const question of Object.keys(answers ?? {})) ids.add(question);
  return [...ids];
}
