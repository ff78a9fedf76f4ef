import type { AttemptColumn, CellProblem, ReadRow } from './attempt-columns.ts';
import type { CodeRuns } from './code-lab-attempt.ts';

/**
 * The CSV export's columns for a code lab task's attempt (code-lab-attempt.ts): empty on
 * every other row. Declared here and placed in the one table of columns (attempt-columns.ts),
 * which writes and reads them. A run with no failing case is written `-` in code_failing.
 */

/** Written for a run where every case passed. */
const NONE = '-';

function runsOf(into: ReadRow): CodeRuns {
  into.attempt.code ??= { runs: 0, passed: 0, total: 0, failing: [], solved: false };
  return into.attempt.code;
}

function count(name: string, field: 'runs' | 'passed' | 'total'): AttemptColumn {
  return {
    name,
    quoted: false,
    required: false,
    value: ({ attempt }) => attempt.code?.[field] ?? '',
    read: (cell, into): CellProblem | void => {
      if (cell === '') return;
      const value = Number(cell);
      if (!Number.isInteger(value) || value < 0) return 'not-a-count';
      runsOf(into)[field] = value;
    },
  };
}

export const CODE_LAB_COLUMNS: readonly AttemptColumn[] = [
  count('code_runs', 'runs'),
  count('code_passed', 'passed'),
  count('code_total', 'total'),
  {
    name: 'code_failing',
    quoted: false,
    required: false,
    value: ({ attempt }) => attempt.code?.failing.map((kind) => kind ?? NONE).join(' ') ?? '',
    read: (cell, into): CellProblem | void => {
      if (cell.trim() === '') return;
      runsOf(into).failing = cell
        .trim()
        .split(/\s+/)
        .map((kind) => (kind === NONE ? null : kind));
    },
  },
  {
    name: 'code_solved',
    quoted: false,
    required: false,
    value: ({ attempt }) => (attempt.code ? String(attempt.code.solved) : ''),
    read: (cell, into) => {
      if (cell !== '') runsOf(into).solved = cell === 'true';
    },
  },
];
