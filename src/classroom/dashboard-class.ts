import { msg, str } from '@lit/localize';
import { ID_COLUMNS } from './attempt-columns.ts';
import { attemptRows, csvHeader } from './attempt-rows.ts';
import { csvTable } from './csv-text.ts';
import { readExportFile } from './dashboard-read-file.ts';
import type { ClassLearner } from './dashboard-learners.ts';
import type { ClassRecord, SkippedFile } from './dashboard-record.ts';
import { NO_OPTION_TEXTS, type OptionText } from './quiz-options.ts';
import { handedInQuestionIds, type SurveyLookup } from './survey-columns.ts';

/**
 * A class's dropped files, read: the records that count and the files skipped with their
 * reason. The same export dropped twice (or copied under another name) counts once; files
 * of one learner are merged later (dashboard-learners.ts).
 */
export interface ClassFiles {
  records: ClassRecord[];
  skipped: SkippedFile[];
}

export interface DroppedFile {
  name: string;
  text: string;
}

/** Reads every file; adds to `earlier` (files dropped before) so that drops can be repeated. */
export function readClassFiles(
  files: readonly DroppedFile[],
  earlier: ClassFiles = { records: [], skipped: [] },
  seen = new Map<string, string>(),
): ClassFiles {
  const records = [...earlier.records];
  const skipped = [...earlier.skipped];
  for (const { name, text } of files) {
    const first = seen.get(text);
    if (first !== undefined) {
      skipped.push({ file: name, reason: msg(str`the same export as ${first}, counted once`) });
      continue;
    }
    const read = readExportFile(name, text);
    if (read.ok) {
      seen.set(text, name);
      records.push(read.record);
    } else skipped.push({ file: read.file, reason: read.reason, ...(read.detail === undefined ? {} : { detail: read.detail }) });
  }
  return { records, skipped };
}

/** The questions some learner's assignment asked (survey-columns.ts): a question none asked has no column. */
const surveyQuestions = (learners: readonly ClassLearner[], surveyById: SurveyLookup) =>
  handedInQuestionIds(
    surveyById,
    learners.map((learner) => learner.survey),
  );

/**
 * The combined CSV: the learners' CSV export's columns and rows (the kept file of each
 * playthrough, so nothing is counted twice), then the file each row came from. Survey
 * columns: the questions the learners' assignments asked, in the order of `surveyById`'s
 * questions (the app's surveys.ts).
 */
export function combinedCsv(learners: readonly ClassLearner[], surveyById: SurveyLookup, optionText: OptionText = NO_OPTION_TEXTS): string {
  const questions = surveyQuestions(learners, surveyById);
  const rows = learners.flatMap((learner) =>
    learner.parts.flatMap((part) => attemptRows({ ...part, survey: learner.survey }, part.attempts, questions, optionText).map((row) => [...row, part.file])),
  );
  return csvTable([...csvHeader(questions), 'file'], rows, ID_COLUMNS);
}

/** The survey CSV: one row per learner who answered, one column per question their assignments asked. */
export function surveyCsv(learners: readonly ClassLearner[], surveyById: SurveyLookup): string {
  const answered = learners.filter((learner) => learner.survey);
  const questions = surveyQuestions(answered, surveyById);
  const header = ['learner_id', 'participant', 'assignment', 'assignment_id', 'class_code', 'survey', ...questions];
  const rows = answered.map((learner) => [
    learner.learnerId,
    learner.participant,
    learner.assignment,
    learner.assignmentId,
    learner.classCode,
    learner.survey?.id ?? '',
    ...questions.map((question) => learner.survey?.answers[question] ?? ''),
  ]);
  return csvTable(header, rows, ID_COLUMNS);
}
