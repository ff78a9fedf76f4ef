import type { SurveyAnswers } from './survey-answers.ts';
import { surveyAsked } from './survey-for-levels.ts';
import type { Survey } from './survey-schema.ts';

export type SurveyLookup = (id: string) => Survey | undefined;

/**
 * Which questions of a survey a learner was asked, as far as their file says: the
 * assignment's levels and the teacher's choice (a JSON export, survey-for-levels.ts), or the
 * survey columns of a CSV export (which has a column for each question asked). Absent or null:
 * the file does not say (free play, older files), so every question of the survey.
 */
export type SurveyAsked = { levels: readonly string[]; choice?: Readonly<Record<string, boolean>> } | { columns: readonly string[] } | null;

/** A survey as a file handed it in: its id, the answers, and what was asked. */
export interface HandedInSurvey {
  id: string;
  answers: SurveyAnswers;
  asked?: SurveyAsked;
}

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
  return handedInQuestionIds(surveyById, [
    ...named.map((id) => (id ? { id, answers: {} } : null)),
    ...answered.map((answers) => (answers ? { id: '', answers } : null)),
  ]);
}

/**
 * The survey columns of a class's files (the combined and the survey CSV): the questions some
 * learner's assignment asked or answered, in the survey's order, then answers to questions
 * the app does not know. A question no assignment asked has no column, so an empty cell means "asked and
 * left open" there too (issue 40).
 */
export function handedInQuestionIds(surveyById: SurveyLookup, surveys: readonly (HandedInSurvey | null | undefined)[]): string[] {
  const asked = new Set<string>();
  const order: string[] = [];
  for (const survey of surveys) {
    const known = survey && surveyById(survey.id);
    if (!known) continue;
    for (const question of known.questions) if (!order.includes(question.id)) order.push(question.id);
    for (const id of askedIds(known, survey.asked)) asked.add(id);
    // An answer always has its column (a file written by hand, or by another version).
    for (const id of Object.keys(survey.answers)) asked.add(id);
  }
  const ids = new Set(order.filter((id) => asked.has(id)));
  for (const survey of surveys) for (const question of Object.keys(survey?.answers ?? {})) ids.add(question);
  return [...ids];
}

function askedIds(survey: Survey, asked: SurveyAsked | undefined): string[] {
  if (!asked) return survey.questions.map((question) => question.id);
  if ('columns' in asked) return survey.questions.filter((question) => asked.columns.includes(question.id)).map((question) => question.id);
  return surveyAsked(survey, asked.levels, asked.choice).questions.map((question) => question.id);
}
