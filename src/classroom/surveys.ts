import defaultSurvey from './surveys/default.survey.json';
import { parseSurvey, type Survey } from './survey-schema.ts';

/**
 * The surveys an assignment can close with, by id. They ship with the app (a link names
 * one, it does not carry it); tests/classroom/survey.test.ts checks each file.
 */
const FILES: readonly unknown[] = [defaultSurvey];

const surveys = new Map<string, Survey>();
for (const file of FILES) {
  const parsed = parseSurvey(file);
  // A broken file is caught by the tests; in the app it is simply not offered.
  if (parsed.ok) surveys.set(parsed.survey.id, parsed.survey);
}

/** The ids of the surveys that can be chosen, in a fixed order. */
export const SURVEY_IDS: readonly string[] = [...surveys.keys()];

export function surveyById(id: string): Survey | undefined {
  return surveys.get(id);
}
