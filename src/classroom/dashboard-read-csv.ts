import { msg, str } from '@lit/localize';
import { HOW_COMPLETED, type HowCompleted } from '../quest/event-log.ts';
import type { TaskAttempt } from './task-attempts.ts';
import { parseCsv } from './csv-text.ts';
import type { FileRead } from './dashboard-record.ts';

/**
 * Reads a learner's CSV export (one row per task attempt, the columns of
 * spec/classroom.md) for the dashboard. Columns are found by name, so their order and any
 * extra columns do not matter. A CSV has no level events or survey answers: such a file
 * counts for the task times and stuck points only.
 */

const REQUIRED = ['participant', 'level', 'task', 'started_at', 'duration_ms', 'active_ms'] as const;

/** The attempt's counts and times and the columns they come from; an empty cell is 0. */
const NUMBER_COLUMNS = {
  durationMs: 'duration_ms',
  activeMs: 'active_ms',
  points: 'points',
  hintsText: 'hints_text',
  hintsGuidance: 'hints_guidance',
  quizAnswers: 'quiz_answers',
} as const;
type Counts = { -readonly [Field in keyof typeof NUMBER_COLUMNS]: number };

export function readCsvExport(file: string, text: string): FileRead {
  const csv = parseCsv(text);
  if (!csv.ok) return { ok: false, file, reason: `damaged CSV: ${csv.error}` };
  const [header, ...rows] = csv.rows;
  if (!header) return { ok: false, file, reason: msg('the file is empty') };
  const column = new Map(header.map((name, index) => [name.trim().toLowerCase(), index]));
  const missing = REQUIRED.filter((name) => !column.has(name));
  if (missing.length > 0) return { ok: false, file, reason: msg(str`not a Ray Tracer Quest CSV export (no column ${missing.map((name) => `"${name}"`).join(', ')})`) };

  const cell = (row: string[], name: string) => row[column.get(name) ?? -1] ?? '';
  const attempts: TaskAttempt[] = [];
  for (const [index, row] of rows.entries()) {
    const line = index + 2;
    const counts = {} as Counts;
    for (const [field, name] of Object.entries(NUMBER_COLUMNS) as [keyof Counts, string][]) {
      const value = cell(row, name) === '' ? 0 : Number(cell(row, name));
      if (!Number.isFinite(value) || value < 0) return { ok: false, file, reason: `damaged CSV: line ${line}: ${name} must be a number of at least 0, got "${cell(row, name)}"` };
      counts[field] = value;
    }
    if (Number.isNaN(Date.parse(cell(row, 'started_at')))) return { ok: false, file, reason: `damaged CSV: line ${line}: started_at is not a date` };
    const completedAt = cell(row, 'completed_at');
    attempts.push({
      level: cell(row, 'level'),
      task: cell(row, 'task'),
      mandatory: cell(row, 'mandatory') === 'true',
      startedAt: cell(row, 'started_at'),
      completedAt: completedAt === '' ? null : completedAt,
      ...counts,
      how: completedAt === '' ? null : howOf(cell(row, 'how'), cell(row, 'shown_by_app') === 'true'),
    });
  }
  const first = rows[0];
  return {
    ok: true,
    record: {
      file,
      participant: first ? cell(first, 'participant') : '',
      assignment: first ? cell(first, 'assignment') : '',
      assignmentId: first ? cell(first, 'assignment_id') : '',
      attempts,
      visits: [],
      survey: null,
    },
  };
}

/** The `how` column; a file without one (written by hand or another tool) has shown_by_app. */
function howOf(how: string, shownByApp: boolean): HowCompleted {
  const known = HOW_COMPLETED.find((name) => name === how);
  return known ?? (shownByApp ? 'shown' : 'done');
}
