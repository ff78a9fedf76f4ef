import type { ClassRecord } from './dashboard-record.ts';

/**
 * What a class made of each code lab (issue 43, spec/code-labs.md §4: "the dashboard shows
 * which cases a class got wrong most often"), from the task attempts' runs
 * (code-lab-attempt.ts): how many learners ran it, how many solved it, and the kinds of the
 * first failing case over all their runs, most common first: the misconceptions.
 */

export interface CodeLabSummary {
  level: string;
  task: string;
  /** Learners with at least one graded run. */
  learners: number;
  /** Of those, the ones whose run passed every case. */
  solved: number;
  /** Each first-failing kind with the number of runs it was first to fail in, most runs first (ties by name). */
  failing: { kind: string; runs: number }[];
}

/** Every code lab task some learner ran, in the order first met. */
export function summarizeCodeLabs(records: readonly ClassRecord[]): CodeLabSummary[] {
  const summaries = new Map<string, CodeLabSummary & { counts: Map<string, number> }>();
  for (const record of records) {
    const seen = new Set<string>();
    for (const attempt of record.attempts) {
      const runs = attempt.code;
      if (!runs || runs.runs === 0) continue;
      const key = `${attempt.level}\u0000${attempt.task}`;
      let summary = summaries.get(key);
      if (!summary) {
        summary = { level: attempt.level, task: attempt.task, learners: 0, solved: 0, failing: [], counts: new Map() };
        summaries.set(key, summary);
      }
      if (!seen.has(key)) {
        seen.add(key);
        summary.learners++;
        if (record.attempts.some((other) => other.level === attempt.level && other.task === attempt.task && other.code?.solved)) summary.solved++;
      }
      for (const kind of runs.failing) if (kind !== null) summary.counts.set(kind, (summary.counts.get(kind) ?? 0) + 1);
    }
  }
  return [...summaries.values()].map(({ counts, ...summary }) => ({
    ...summary,
    failing: [...counts].map(([kind, runs]) => ({ kind, runs })).sort((a, b) => b.runs - a.runs || a.kind.localeCompare(b.kind)),
  }));
}
