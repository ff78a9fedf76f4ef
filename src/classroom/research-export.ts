import { ID_COLUMNS, SURVEY_PREFIX } from './attempt-columns.ts';
import { attemptRows, csvHeader } from './attempt-rows.ts';
import { csvTable } from './csv-text.ts';
import type { ClassLearner } from './dashboard-learners.ts';
import { handedInQuestionIds, type SurveyLookup } from './survey-columns.ts';
import { NO_OPTION_TEXTS, type OptionText } from './quiz-options.ts';

/**
 * The research export: the combined CSV's rows (dashboard-class.ts) with what a study's
 * data set does not need taken out, so that it can be shared with a supervisor or an
 * ethics board as pseudonymous data (AVG/GDPR art. 89: data minimisation for research).
 *
 * - No wall-clock times: `started_at` and `completed_at` become `started_s` and
 *   `completed_s`, seconds (to 0.1 s) since the learner's first logged task, so the order and
 *   the gaps between a learner's tasks survive but not the day, the hour or the lesson.
 * - No `install_id` (a device id) and no `file` column (file names carry dates).
 * - Free text (the survey's text questions, and answers to questions the app does not know,
 *   which may be text) is left out, unless `freeText` is set; then its columns are marked
 *   `_free_text`, for a researcher to read before sharing: a pupil can type anything there.
 */

export interface ResearchOptions {
  freeText: boolean;
}

const REMOVED = new Set(['install_id']);
const TIMES: Record<string, string> = { started_at: 'started_s', completed_at: 'completed_s' };
export const FREE_TEXT_SUFFIX = '_free_text';

export function researchCsv(
  learners: readonly ClassLearner[],
  surveyById: SurveyLookup,
  options: ResearchOptions,
  optionText: OptionText = NO_OPTION_TEXTS,
): string {
  const allQuestions = handedInQuestionIds(
    surveyById,
    learners.map((learner) => learner.survey),
  );
  const known = new Map(learners.flatMap((learner) => surveyById(learner.survey?.id ?? '')?.questions ?? []).map((question) => [question.id, question]));
  const isFreeText = (id: string) => (known.get(id)?.type ?? 'text') === 'text';
  const questions = allQuestions.filter((id) => options.freeText || !isFreeText(id));
  const header = csvHeader(questions);
  const kept = header.map((name, index) => ({ name, index })).filter(({ name }) => !REMOVED.has(name));
  const rows = learners.flatMap((learner) => {
    const start = Math.min(...learner.parts.flatMap((part) => part.attempts.map((attempt) => Date.parse(attempt.startedAt))));
    const seconds = (iso: string | number | boolean) => (iso === '' ? '' : Math.round((Date.parse(String(iso)) - start) / 100) / 10);
    return learner.parts.flatMap((part) =>
      attemptRows({ ...part, survey: learner.survey }, part.attempts, questions, optionText).map((row) =>
        kept.map(({ name, index }) => (name in TIMES ? seconds(row[index]) : row[index])),
      ),
    );
  });
  const names = kept.map(
    ({ name }) => TIMES[name] ?? (name.startsWith(SURVEY_PREFIX) && isFreeText(name.slice(SURVEY_PREFIX.length)) ? `${name}${FREE_TEXT_SUFFIX}` : name),
  );
  return csvTable(names, rows, ID_COLUMNS);
}
