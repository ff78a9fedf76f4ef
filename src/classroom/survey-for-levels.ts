import type { Assignment } from './assignment.ts';
import type { Survey, SurveyQuestion } from './survey-schema.ts';

/**
 * The survey as an assignment asks it. By default a question that names levels (the idea it
 * asks about is taught there, e.g. attenuation in 09-attenuation) is asked only when the
 * assignment has one of them, so that pupils who played levels 1–4 are not asked how well
 * the game taught soft shadows (issue 40). The teacher may tick any question on or off
 * (Assignment.surveyQuestions); that choice wins over the default.
 */

/** Whether the default asks `question` of an assignment with these levels (null: a teacher's preview, every question). */
export function fitsLevels(question: SurveyQuestion, levels: readonly string[] | null): boolean {
  return !levels || !question.levels || question.levels.some((level) => levels.includes(level));
}

/** Whether the assignment asks `question`: the teacher's choice when there is one, else the default. */
export function isAsked(question: SurveyQuestion, levels: readonly string[] | null, choice: Assignment['surveyQuestions']): boolean {
  return choice?.[question.id] ?? fitsLevels(question, levels);
}

/** The survey with only the questions the assignment asks, in the survey's order. */
export function surveyAsked(survey: Survey, levels: readonly string[] | null, choice?: Assignment['surveyQuestions']): Survey {
  const questions = survey.questions.filter((question) => isAsked(question, levels, choice));
  if (questions.length > 0) return { ...survey, questions };
  // No question left (the teacher page does not let this happen; a hand-edited link might):
  // the default's questions, or all of them when even those are none (the schema needs one).
  const fitting = survey.questions.filter((question) => fitsLevels(question, levels));
  return fitting.length > 0 ? { ...survey, questions: fitting } : survey;
}

/** The survey's questions the default asks of these levels (no teacher's choice). */
export function surveyForLevels(survey: Survey, levels: readonly string[] | null): Survey {
  return surveyAsked(survey, levels);
}

/**
 * The teacher's choice without the entries that say what the default says anyway, or that
 * name questions the survey does not have: undefined when nothing is left. It keeps the link
 * short (assignment-compact.ts) and its id the same as without a choice.
 */
export function ownSurveyChoice(survey: Survey | undefined, levels: readonly string[], choice: Assignment['surveyQuestions']): Assignment['surveyQuestions'] {
  if (!survey || !choice) return undefined;
  const own = Object.fromEntries(
    survey.questions
      .filter((question) => question.id in choice && choice[question.id] !== fitsLevels(question, levels))
      .map((question) => [question.id, choice[question.id]]),
  );
  return Object.keys(own).length > 0 ? own : undefined;
}
