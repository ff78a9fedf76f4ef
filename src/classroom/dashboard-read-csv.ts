import { msg, str } from '@lit/localize';
import { HOW_COMPLETED, type HowCompleted } from '../quest/event-log.ts';
import { TASK_KINDS, type TaskKind } from '../quest/goal.ts';
import type { TaskAttempt } from './task-attempts.ts';
import { parseCsv } from './csv-text.ts';
import { SURVEY_PREFIX } from './attempt-rows.ts';
import type { ClassRecord, FileRead } from './dashboard-record.ts';
import type { SurveyAnswers } from './survey-answers.ts';

/**
 * Reads a learner's CSV export (one row per task attempt, the columns of
 * docs/classroom.md) for the dashboard. Columns are found by name, so their order and any
 * extra columns do not matter, and files from before a column existed still read. A CSV
 * has no level events: such a file counts for the task times, stuck points and (from its
 * mandatory column) passing.
 */

const REQUIRED = ['participant', 'level', 'task', 'started_at', 'duration_ms', 'active_ms'] as const;

/**
 * The attempt's counts and times and the columns they come from; an empty cell is 0.
 * `hints_opened` is not read: it is hints_text + hints_guidance. A file from before
 * hints_offered has no offers, and its hints_text and hints_guidance also count the
 * rungs that came by themselves after idle time (docs/classroom.md).
 */
const NUMBER_COLUMNS = {
  durationMs: 'duration_ms',
  activeMs: 'active_ms',
  points: 'points',
  hintsText: 'hints_text',
  hintsGuidance: 'hints_guidance',
  hintsOffered: 'hints_offered',
  quizAnswers: 'quiz_answers',
} as const;
type Counts = { -readonly [Field in keyof typeof NUMBER_COLUMNS]: number };

export function readCsvExport(file: string, text: string): FileRead {
  const csv = parseCsv(text);
  if (!csv.ok) return { ok: false, file, reason: msg(str`damaged CSV: a quoted field that starts on line ${csv.openQuoteLine} is never closed`) };
  const [header, ...rows] = csv.rows;
  if (!header) return { ok: false, file, reason: msg('the file is empty') };
  const names = header.map((name) => name.trim().toLowerCase());
  const column = new Map(names.map((name, index) => [name, index]));
  const missing = REQUIRED.filter((name) => !column.has(name));
  if (missing.length > 0) return { ok: false, file, reason: msg(str`not a Ray Tracer Quest CSV export (no column ${missing.map((name) => `"${name}"`).join(', ')})`) };

  const cell = (row: string[], name: string) => row[column.get(name) ?? -1] ?? '';
  const attempts: TaskAttempt[] = [];
  for (const [index, row] of rows.entries()) {
    const line = index + 2;
    const counts = {} as Counts;
    for (const [field, name] of Object.entries(NUMBER_COLUMNS) as [keyof Counts, string][]) {
      const value = cell(row, name) === '' ? 0 : Number(cell(row, name));
      if (!Number.isFinite(value) || value < 0) return { ok: false, file, reason: msg(str`damaged CSV: line ${line}: ${name} must be a number of at least 0, got "${cell(row, name)}"`) };
      counts[field] = value;
    }
    if (Number.isNaN(Date.parse(cell(row, 'started_at')))) return { ok: false, file, reason: msg(str`damaged CSV: line ${line}: started_at is not a date`) };
    const completedAt = cell(row, 'completed_at');
    const quizCorrect = cell(row, 'quiz_correct');
    attempts.push({
      level: cell(row, 'level'),
      task: cell(row, 'task'),
      mandatory: cell(row, 'mandatory') === 'true',
      kind: TASK_KINDS.find((kind): kind is TaskKind => kind === cell(row, 'kind')) ?? null,
      startedAt: cell(row, 'started_at'),
      completedAt: completedAt === '' ? null : completedAt,
      ...counts,
      how: completedAt === '' ? null : howOf(cell(row, 'how'), cell(row, 'shown_by_app') === 'true'),
      quizCorrect: quizCorrect === '' ? null : quizCorrect === 'true',
    });
  }
  const first = rows[0] ?? [];
  const participant = cell(first, 'participant');
  return {
    ok: true,
    record: {
      file,
      participant,
      learnerId: cell(first, 'learner_id') || participant || `file:${file}`,
      attemptId: cell(first, 'attempt_id') || `file:${file}`,
      installId: cell(first, 'install_id'),
      assignment: cell(first, 'assignment'),
      assignmentId: cell(first, 'assignment_id'),
      classCode: cell(first, 'class_code'),
      attempts,
      visits: [],
      survey: surveyOf(cell(first, 'survey'), names, first),
    },
  };
}

/** The `how` column; a file without one (written by hand or another tool) has shown_by_app. */
function howOf(how: string, shownByApp: boolean): HowCompleted {
  const known = HOW_COMPLETED.find((name) => name === how);
  return known ?? (shownByApp ? 'shown' : 'done');
}

/**
 * The survey columns of a row. A cell that is a plain number was a scale's or a number
 * question's answer (choices are written as their option's id, which starts with a letter).
 */
function surveyOf(id: string, names: readonly string[], row: readonly string[]): ClassRecord['survey'] {
  if (id === '') return null;
  const answers: SurveyAnswers = {};
  names.forEach((name, index) => {
    const value = row[index] ?? '';
    if (!name.startsWith(SURVEY_PREFIX) || value === '') return;
    answers[name.slice(SURVEY_PREFIX.length)] = /^-?\d+(\.\d+)?$/.test(value) ? Number(value) : value;
  });
  return { id, answers };
}
