import { msg, str } from '@lit/localize';
import type { HowCompleted } from '../quest/event-log.ts';
import { ATTEMPT_COLUMNS, emptyReadRow, SURVEY_PREFIX, type CellProblem, type ReadRow } from './attempt-columns.ts';
import { parseCsv } from './csv-text.ts';
import { learnerKey, normalParticipantCode } from './participant-code.ts';
import type { ClassRecord, FileRead } from './dashboard-record.ts';
import type { SurveyAnswers } from './survey-answers.ts';

/**
 * Reads a learner's CSV export (one row per task attempt, the columns of
 * attempt-columns.ts and docs/classroom.md) for the dashboard. Columns are found by name,
 * so their order and any extra columns do not matter, and files from before a column
 * existed still read (its cells as empty: a count as 0). A CSV has no level events: such a
 * file counts for the task times, stuck points and (from its mandatory column) passing.
 * `hints_opened` and `attempts` are not read: they follow from other columns. A file from
 * before hints_offered has no offers, and its hints_text and hints_guidance also count the
 * rungs that came by themselves after idle time (docs/classroom.md).
 */

export function readCsvExport(file: string, text: string): FileRead {
  const csv = parseCsv(text);
  if (!csv.ok) return { ok: false, file, reason: msg(str`damaged CSV: a quoted field that starts on line ${csv.openQuoteLine} is never closed`) };
  const [header, ...rows] = csv.rows;
  if (!header) return { ok: false, file, reason: msg('the file is empty') };
  const names = header.map((name) => name.trim().toLowerCase());
  const column = new Map(names.map((name, index) => [name, index]));
  const missing = ATTEMPT_COLUMNS.filter(({ name, required }) => required && !column.has(name)).map(({ name }) => name);
  if (missing.length > 0)
    return { ok: false, file, reason: msg(str`not a Ray Tracer Quest CSV export (no column ${missing.map((name) => `"${name}"`).join(', ')})`) };

  const readRow = (row: readonly string[]) => {
    const into = emptyReadRow();
    for (const { name, read } of ATTEMPT_COLUMNS) {
      const cell = row[column.get(name) ?? -1] ?? '';
      const problem = read?.(cell, into);
      if (problem) return { problem, name, cell };
    }
    return { into };
  };
  const attempts: ReadRow['attempt'][] = [];
  for (const [index, row] of rows.entries()) {
    const read = readRow(row);
    if (!read.into) return { ok: false, file, reason: problemText(read.problem, index + 2, read.name, read.cell) };
    const { attempt, shownByApp } = read.into;
    attempts.push({ ...attempt, how: attempt.completedAt === null ? null : howOf(attempt.how, shownByApp) });
  }
  const first = rows[0] ?? [];
  const owner = readRow(first).into?.owner ?? emptyReadRow().owner;
  return {
    ok: true,
    record: {
      file,
      // `5h2-03` and `5H2-03` are one learner (participant-code.ts).
      participant: normalParticipantCode(owner.participant),
      learnerId: learnerKey(owner.learnerId || owner.participant, owner.participant) || `file:${file}`,
      attemptId: owner.attemptId || `file:${file}`,
      installId: owner.installId,
      assignment: owner.assignment,
      assignmentId: owner.assignmentId,
      classCode: owner.classCode,
      appVersion: owner.appVersion,
      utcOffsetMin: owner.utcOffsetMin,
      attempts,
      visits: [],
      survey: surveyOf(owner.surveyId, names, first),
      conceptTest: owner.conceptTest.pre || owner.conceptTest.post ? owner.conceptTest : null,
    },
  };
}

function problemText(problem: CellProblem, line: number, name: string, cell: string): string {
  switch (problem) {
    case 'not-a-count':
      return msg(str`damaged CSV: line ${line}: ${name} must be a number of at least 0, got "${cell}"`);
    case 'not-a-date':
      // Only started_at is checked as a date (completed_at may be empty).
      return msg(str`damaged CSV: line ${line}: started_at is not a date`);
  }
}

/** How a completed attempt ended; a file without a `how` column (written by hand or another tool) has shown_by_app. */
function howOf(how: HowCompleted | null, shownByApp: boolean): HowCompleted {
  return how ?? (shownByApp ? 'shown' : 'done');
}

/**
 * The survey columns of a row. A cell that is a plain number was a scale's or a number
 * question's answer (choices are written as their option's id, which starts with a letter).
 */
function surveyOf(id: string, names: readonly string[], row: readonly string[]): ClassRecord['survey'] {
  if (id === '') return null;
  const answers: SurveyAnswers = {};
  // The file has a column for each question the learner's assignment asked (export-csv.ts).
  const columns = names.filter((name) => name.startsWith(SURVEY_PREFIX)).map((name) => name.slice(SURVEY_PREFIX.length));
  names.forEach((name, index) => {
    const value = row[index] ?? '';
    if (!name.startsWith(SURVEY_PREFIX) || value === '') return;
    answers[name.slice(SURVEY_PREFIX.length)] = /^-?\d+(\.\d+)?$/.test(value) ? Number(value) : value;
  });
  return { id, answers, asked: { columns } };
}
