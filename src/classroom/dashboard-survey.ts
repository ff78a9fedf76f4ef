import type { LocalizedText } from '../quest/localized-text.ts';
import type { ClassRecord } from './dashboard-record.ts';
import { fiveNumbers, type FiveNumbers } from './dashboard-stats.ts';
import type { SurveyAnswers } from './survey-answers.ts';
import type { Survey } from './survey-schema.ts';

/**
 * The class's survey answers per question, read with the survey's own definition (the
 * export names the survey by id): scales as counts per step (the stacked Likert bars of
 * the thesis's Figure 5.1), choices as counts per option, numbers as five numbers, free
 * text as the list of remarks. An answer that does not fit its question (a hand-edited
 * file) is not counted.
 */

export interface ScaleSummary {
  id: string;
  text: LocalizedText;
  min: number;
  max: number;
  minLabel: LocalizedText;
  maxLabel: LocalizedText;
  /** counts[i] learners answered min + i. */
  counts: number[];
  answered: number;
}

export interface ChoiceSummary {
  id: string;
  text: LocalizedText;
  options: { id: string; text: LocalizedText; count: number }[];
  answered: number;
}

export interface NumberSummary {
  id: string;
  text: LocalizedText;
  stats: FiveNumbers | null;
}

export interface TextSummary {
  id: string;
  text: LocalizedText;
  answers: string[];
}

export interface SurveySummary {
  id: string;
  title: LocalizedText;
  /** Learners who handed this survey in. */
  respondents: number;
  scales: ScaleSummary[];
  choices: ChoiceSummary[];
  numbers: NumberSummary[];
  texts: TextSummary[];
}

export interface SurveysSummary {
  surveys: SurveySummary[];
  /** Ids of surveys this version of the app does not know, with how many learners answered them. */
  unknown: { id: string; respondents: number }[];
}

/** Every survey that was answered, counted with its definition from `surveyById`. */
export function summarizeSurveys(records: readonly ClassRecord[], surveyById: (id: string) => Survey | undefined): SurveysSummary {
  const answered = new Map<string, SurveyAnswers[]>();
  for (const record of records) if (record.survey) answered.set(record.survey.id, [...(answered.get(record.survey.id) ?? []), record.survey.answers]);
  const summary: SurveysSummary = { surveys: [], unknown: [] };
  for (const [id, answerSets] of answered) {
    const survey = surveyById(id);
    if (survey) summary.surveys.push(summarizeSurvey(survey, answerSets));
    else summary.unknown.push({ id, respondents: answerSets.length });
  }
  return summary;
}

function summarizeSurvey(survey: Survey, answerSets: readonly SurveyAnswers[]): SurveySummary {
  const summary: SurveySummary = { id: survey.id, title: survey.title, respondents: answerSets.length, scales: [], choices: [], numbers: [], texts: [] };
  for (const question of survey.questions) {
    const values = answerSets.map((answers) => answers[question.id]).filter((value) => value !== undefined);
    const numbers = values.filter((value): value is number => typeof value === 'number' && Number.isFinite(value));
    const { id, text } = question;
    switch (question.type) {
      case 'scale': {
        const counts = Array.from({ length: question.max - question.min + 1 }, (_, step) => numbers.filter((value) => value === question.min + step).length);
        const { min, max, minLabel, maxLabel } = question;
        summary.scales.push({ id, text, min, max, minLabel, maxLabel, counts, answered: counts.reduce((a, b) => a + b, 0) });
        break;
      }
      case 'choice': {
        const options = question.options.map((option) => ({ id: option.id, text: option.text, count: values.filter((value) => value === option.id).length }));
        summary.choices.push({ id, text, options, answered: options.reduce((total, option) => total + option.count, 0) });
        break;
      }
      case 'number':
        summary.numbers.push({ id, text, stats: fiveNumbers(numbers) });
        break;
      case 'text':
        summary.texts.push({ id, text, answers: values.filter((value): value is string => typeof value === 'string') });
        break;
    }
  }
  return summary;
}
