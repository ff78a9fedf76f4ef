import type { AttemptColumn, CellProblem, ReadRow } from './attempt-columns.ts';
import type { ChallengeTries } from './challenge-attempt.ts';

/**
 * The CSV export's columns for a challenge task's attempt (challenge-attempt.ts): empty on
 * every other row. Declared here and placed in the one table of columns (attempt-columns.ts),
 * which writes and reads them.
 */

/** The row's tries, made once its first challenge cell is read. */
function triesOf(into: ReadRow): ChallengeTries {
  into.attempt.challenge ??= { renders: 0, changes: 0, rays: 0, scores: [], stars: null };
  return into.attempt.challenge;
}

function count(name: string, field: 'renders' | 'changes' | 'rays'): AttemptColumn {
  return {
    name,
    quoted: false,
    required: false,
    value: ({ attempt }) => attempt.challenge?.[field] ?? '',
    read: (cell, into): CellProblem | void => {
      if (cell === '') return;
      const value = Number(cell);
      if (!Number.isInteger(value) || value < 0) return 'not-a-count';
      triesOf(into)[field] = value;
    },
  };
}

export const CHALLENGE_COLUMNS: readonly AttemptColumn[] = [
  count('challenge_renders', 'renders'),
  count('challenge_changes', 'changes'),
  count('challenge_rays', 'rays'),
  {
    name: 'challenge_scores',
    quoted: false,
    required: false,
    value: ({ attempt }) => attempt.challenge?.scores.join(' ') ?? '',
    read: (cell, into): CellProblem | void => {
      if (cell.trim() === '') return;
      const scores = cell.trim().split(/\s+/).map(Number);
      if (scores.some((score) => !Number.isFinite(score) || score < 0 || score > 100)) return 'not-a-count';
      triesOf(into).scores = scores;
    },
  },
  {
    name: 'challenge_stars',
    quoted: false,
    required: false,
    value: ({ attempt }) => attempt.challenge?.stars ?? '',
    read: (cell, into): CellProblem | void => {
      if (cell === '') return;
      const stars = Number(cell);
      if (stars !== 1 && stars !== 2 && stars !== 3) return 'not-a-count';
      triesOf(into).stars = stars;
    },
  },
];
