import { z } from 'zod';
import { describeIssue, formatIssues, reasonIssue, withReason } from '../scene/scene-issues.ts';
import { kebabId } from '../quest/kebab-id.ts';
import { localizedTextSchema } from '../quest/localized-text.ts';
import { listOf } from '../scene/scene-schema-parts.ts';

/**
 * A closing questionnaire (spec/classroom.md "Survey"), a data file in ./surveys. Four kinds
 * of question: one choice of several, a scale with labelled ends (1–5, 1–10), a number, and
 * free text; each required or optional. Texts are `{ en, nl }` like level texts.
 */

/** More than any questionnaire a class answers; it keeps a damaged file from costing seconds. */
export const QUESTIONS_MAX = 100;
const OPTIONS_MAX = 20;

const common = {
  id: kebabId(),
  text: localizedTextSchema,
  /** Asked only in an assignment with at least one of these levels (a question on what they teach); absent: always (survey-for-levels.ts). */
  levels: z.array(kebabId()).min(1).max(100).optional(),
};

const choiceSchema = z.strictObject({
  ...common,
  type: z.literal('choice'),
  required: z.boolean().default(true),
  options: listOf(z.strictObject({ id: kebabId(), text: localizedTextSchema }), [2, OPTIONS_MAX]),
});

const scaleSchema = z
  .strictObject({
    ...common,
    type: z.literal('scale'),
    required: z.boolean().default(true),
    min: z.number().int(),
    max: z.number().int(),
    minLabel: localizedTextSchema,
    maxLabel: localizedTextSchema,
  })
  // More than eleven steps is no longer a scale one can answer at a glance.
  .refine((scale) => scale.max > scale.min && scale.max - scale.min <= 10, { error: (issue) => withReason(issue, { code: 'scaleSteps' }), path: ['max'] });

const numberSchema = z.strictObject({
  ...common,
  type: z.literal('number'),
  required: z.boolean().default(true),
  min: z.number().optional(),
  max: z.number().optional(),
  /** Whole numbers only (ages, minutes). */
  integer: z.boolean().default(true),
});

const textSchema = z.strictObject({
  ...common,
  type: z.literal('text'),
  required: z.boolean().default(false),
  maxLength: z.number().int().min(1).max(10_000).default(2000),
});

export const surveyQuestionSchema = z.discriminatedUnion('type', [choiceSchema, scaleSchema, numberSchema, textSchema]);

export const surveySchema = z
  .strictObject({
    version: z.literal(1),
    id: kebabId(),
    title: localizedTextSchema,
    intro: localizedTextSchema.optional(),
    questions: listOf(surveyQuestionSchema, [1, QUESTIONS_MAX]),
  })
  .superRefine((survey, context) => {
    const seen = new Set<string>();
    survey.questions.forEach((question, index) => {
      if (seen.has(question.id)) context.addIssue(reasonIssue(['questions', index, 'id'], question.id, { code: 'usedMoreThanOnce', value: question.id }));
      seen.add(question.id);
    });
  });

export type Survey = z.output<typeof surveySchema>;
export type SurveyQuestion = Survey['questions'][number];

export type SurveyParseResult = { ok: true; survey: Survey } | { ok: false; errors: string[] };

export function parseSurvey(input: unknown): SurveyParseResult {
  const result = surveySchema.safeParse(input, { error: describeIssue });
  return result.success ? { ok: true, survey: result.data } : { ok: false, errors: formatIssues(result.error.issues) };
}
