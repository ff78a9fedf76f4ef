import type { ClassRecord } from './dashboard-record.ts';
import { fiveNumbers, type FiveNumbers } from './dashboard-stats.ts';
import type { TaskKind } from '../quest/goal.ts';
import { hintsOpened } from './task-attempts.ts';

/**
 * A class at a glance (spec/classroom.md "Teacher dashboard"): per level and task how long
 * learners took, where they got stuck and how many finished.
 *
 * A learner's time for a task is the active time (tab visible) of all their attempts at it
 * until it was completed, by themselves or by "show me"; skipped and unfinished tasks have
 * no time. A level's time is the active time of the learner's visits to it, counted for
 * those who passed it. Levels are in id order (ids start with their number), tasks in the
 * order learners met them.
 */

export interface TaskSummary {
  level: string;
  task: string;
  mandatory: boolean;
  /** info, quiz or do, as the files say; null when they do not (logs before 0.1). */
  kind: TaskKind | null;
  /** Learners who were shown the task. */
  learners: number;
  /** Learners by how they completed it; the rest did not finish it. */
  done: number;
  shown: number;
  skipped: number;
  /** Active milliseconds per learner who completed it (done or shown), in learner order. */
  times: number[];
  stats: FiveNumbers | null;
  /** Text hints and guidance rings opened, in total (hints offered after idle time count once opened). */
  hintsText: number;
  hintsGuidance: number;
  /** Learners who opened at least one hint. */
  learnersWithHints: number;
  /** Learners who opened a hint or used "show me", or (a mandatory task) did not finish it. */
  learnersNeedingHelp: number;
}

export interface LevelSummary {
  level: string;
  /** Learners who opened the level (or, from a CSV export, were shown one of its tasks). */
  learners: number;
  passed: number;
  /** Active milliseconds per learner who passed. */
  times: number[];
  stats: FiveNumbers | null;
  tasks: TaskSummary[];
}

const byId = (a: string, b: string) => a.localeCompare(b, 'en', { numeric: true });

/** Per-level and per-task figures of all records. */
export function summarizeLevels(records: readonly ClassRecord[]): LevelSummary[] {
  const levelIds = new Set<string>();
  for (const record of records) {
    for (const visit of record.visits) levelIds.add(visit.level);
    for (const attempt of record.attempts) levelIds.add(attempt.level);
  }
  return [...levelIds].sort(byId).map((level) => summarizeLevel(level, records));
}

/** One learner in one level: their active time there and whether they passed; null when they never came. */
export function learnerInLevel(record: ClassRecord, level: string): { activeMs: number; passed: boolean } | null {
  const visits = record.visits.filter((visit) => visit.level === level);
  const attempts = record.attempts.filter((attempt) => attempt.level === level);
  if (visits.length === 0 && attempts.length === 0) return null;
  // A CSV export has no level events: passed is then "every mandatory task completed".
  const completed = new Set(attempts.filter((attempt) => attempt.how !== null).map((attempt) => attempt.task));
  if (record.visits.length > 0) return { activeMs: sum(visits, (visit) => visit.activeMs), passed: visits.some((visit) => visit.passed) };
  return { activeMs: sum(attempts, (attempt) => attempt.activeMs), passed: attempts.every((attempt) => !attempt.mandatory || completed.has(attempt.task)) };
}

function summarizeLevel(level: string, records: readonly ClassRecord[]): LevelSummary {
  let learners = 0;
  const times: number[] = [];
  for (const record of records) {
    const here = learnerInLevel(record, level);
    if (!here) continue;
    learners++;
    if (here.passed) times.push(here.activeMs);
  }
  const taskIds = [...new Set(records.flatMap((record) => record.attempts.filter((attempt) => attempt.level === level).map((attempt) => attempt.task)))];
  return { level, learners, passed: times.length, times, stats: fiveNumbers(times), tasks: taskIds.map((task) => summarizeTask(level, task, records)) };
}

function summarizeTask(level: string, task: string, records: readonly ClassRecord[]): TaskSummary {
  const summary: TaskSummary = {
    level,
    task,
    mandatory: false,
    kind: null,
    learners: 0,
    done: 0,
    shown: 0,
    skipped: 0,
    times: [],
    stats: null,
    hintsText: 0,
    hintsGuidance: 0,
    learnersWithHints: 0,
    learnersNeedingHelp: 0,
  };
  for (const record of records) {
    const attempts = record.attempts.filter((attempt) => attempt.level === level && attempt.task === task);
    if (attempts.length === 0) continue;
    summary.learners++;
    summary.mandatory ||= attempts[0].mandatory;
    summary.kind ??= attempts[0].kind;
    summary.hintsText += sum(attempts, (attempt) => attempt.hintsText);
    summary.hintsGuidance += sum(attempts, (attempt) => attempt.hintsGuidance);
    const opened = sum(attempts, hintsOpened);
    if (opened > 0) summary.learnersWithHints++;
    const finished = attempts.findIndex((attempt) => attempt.how !== null);
    const how = attempts[finished]?.how ?? null;
    if (opened > 0 || how === 'shown' || (how === null && summary.mandatory)) summary.learnersNeedingHelp++;
    if (!how) continue;
    summary[how]++;
    if (how !== 'skipped') summary.times.push(sum(attempts.slice(0, finished + 1), (attempt) => attempt.activeMs));
  }
  summary.stats = fiveNumbers(summary.times);
  return summary;
}

function sum<Item>(items: readonly Item[], value: (item: Item) => number): number {
  return items.reduce((total, item) => total + value(item), 0);
}

/** A task the learner could leave out: not required, and not an info step (which is read, not done). */
export function isOptionalTask(task: Pick<TaskSummary, 'mandatory' | 'kind'>): boolean {
  return !task.mandatory && task.kind !== 'info';
}

/** A task's share of learners who completed it (done or shown), 0..1; 0 when none saw it. */
export function completionRate(task: Pick<TaskSummary, 'learners' | 'done' | 'shown'>): number {
  return task.learners === 0 ? 0 : (task.done + task.shown) / task.learners;
}
