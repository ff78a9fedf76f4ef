import type { LoggedEvent } from '../quest/event-log.ts';

/**
 * A code lab task's runs within one attempt, read from its `code.graded` events (issue 43,
 * spec/code-labs.md §4): how many times the learner pressed Run tests and was graded, how
 * the last run went, the first failing case's kind at each run (the misconceptions met, in
 * order), and whether a run passed every case.
 */
export interface CodeRuns {
  runs: number;
  /** Cases passed at the last run, of `total`. */
  passed: number;
  total: number;
  /** Per run, in order: the kind of its first failing case, or null when all passed. */
  failing: (string | null)[];
  /** Some run passed every case. */
  solved: boolean;
}

type CodeRun = Extract<LoggedEvent, { type: 'code.graded' }>;

/** The runs with one more. */
export function addCodeRun(runs: CodeRuns | undefined, event: CodeRun): CodeRuns {
  const before = runs ?? { runs: 0, passed: 0, total: 0, failing: [], solved: false };
  return {
    runs: before.runs + 1,
    passed: event.passed,
    total: event.total,
    failing: [...before.failing, event.failed],
    solved: before.solved || event.passed === event.total,
  };
}
