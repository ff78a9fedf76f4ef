import type { Survey } from './survey-schema.ts';

/**
 * The survey as an assignment asks it: a question that names levels (the idea it asks about
 * is taught there, e.g. attenuation in 09-attenuation) only when the assignment has one of
 * them, so that pupils who played levels 1–4 are not asked how well the game taught soft
 * shadows (issue 40). Without an assignment's levels (a teacher's preview) every question.
 */
export function surveyForLevels(survey: Survey, levels: readonly string[] | null): Survey {
  if (!levels) return survey;
  const questions = survey.questions.filter((question) => !question.levels || question.levels.some((level) => levels.includes(level)));
  // A survey whose every question names other levels keeps them all rather than none (the schema needs one).
  return questions.length > 0 ? { ...survey, questions } : survey;
}
