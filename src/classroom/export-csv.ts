import { readLog } from './task-attempts.ts';
import { ID_COLUMNS } from './attempt-columns.ts';
import { attemptRows, csvHeader } from './attempt-rows.ts';
import { csvTable } from './csv-text.ts';
import { exportOwner, type ExportInput } from './export-context.ts';
import { surveyQuestionIds } from './survey-columns.ts';
import { NO_OPTION_TEXTS } from './quiz-options.ts';
import { surveyById } from './surveys.ts';
import { surveyAsked } from './survey-for-levels.ts';

/**
 * The CSV export (spec/classroom.md; every column is defined in docs/classroom.md): one row
 * per task attempt, for a spreadsheet, R or pandas.
 *
 * An attempt runs from the moment the task became the learner's (an optional task: from
 * their first move towards it) to its completion; leaving the level (or closing the page)
 * first ends it unfinished, with an empty completed_at, and coming back starts the next
 * attempt. `attempts` is the attempt's number for its task (1, 2, …), so the last row of a
 * task says how many it took. `active_ms` leaves out the time the tab was hidden or the
 * page closed. Times are ISO 8601 in UTC; utc_offset_min turns them into the pupil's clock time. The columns and rows are the dashboard's
 * combined CSV's (attempt-rows.ts), so the two files always agree.
 *
 * Encoding: UTF-8 with a byte-order mark and CRLF line ends (RFC 4180). Without the mark,
 * Excel reads UTF-8 as the local code page and mangles names and typed text; R, Python and
 * LibreOffice skip it. Learner-typed fields that start like a formula get an apostrophe
 * (csv-text.ts), so opening the file cannot run anything; identifiers are always quoted.
 *
 * Survey columns are the questions the assignment asked (survey-for-levels.ts): a question
 * the teacher left out, or that does not fit the levels, has no column, so an empty cell
 * always means "asked and left open".
 */

export const BOM = '\uFEFF';

export function exportCsv(input: ExportInput): string {
  const owner = exportOwner(input);
  const questions = surveyQuestionIds(askedSurvey(input), [input.survey?.survey, input.assignment?.survey], [input.survey?.answers]);
  return (
    BOM + csvTable(csvHeader(questions), attemptRows(owner, readLog(input.progress.log).attempts, questions, input.optionText ?? NO_OPTION_TEXTS), ID_COLUMNS)
  );
}

/** The surveys as this learner's assignment asked them (free play: whole). */
function askedSurvey({ assignment }: ExportInput) {
  return (id: string) => {
    const survey = surveyById(id);
    return survey && assignment ? surveyAsked(survey, assignment.levels, assignment.surveyQuestions) : survey;
  };
}
