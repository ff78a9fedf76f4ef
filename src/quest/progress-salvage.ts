import type { z } from 'zod';
import { describeIssue, formatIssues } from '../scene/scene-issues.ts';
import { isRecord } from '../util/is-record.ts';
import { progressSchema, type Progress } from './progress.ts';

/**
 * Saved progress with a damaged part keeps the rest. One bad event among fifty, a language
 * code this version does not know or a badge of an unknown kind once sent the learner back
 * to 0 points; now the smallest part that holds the damage is left out (or set to what it
 * can be worked out from), and each such change is noted as a `path: reason` line:
 *
 * - an event of the log, a badge, a completed task: left out;
 * - a setting: its default; the sandbox scene or the level to resume: none;
 * - a task's points: 0, which the game works out again from the level file (progress-reconcile.ts);
 *   a quiz task's `correct`: left out;
 * - a level's hint count: the hints its log shows; an epoch: left out (the progress merges);
 * - the log's start time: the time of this repair;
 * - events out of time order: the fewest are left out that put the rest in order;
 * - fields this version does not know: left out;
 * - a `levels`, `badges` or `log` that is not one at all: left out whole;
 * - one lab's code that is not text or is too long: left out, and `code` that is not a
 *   record at all: left out whole (the code kept in the browser stays as it is).
 *
 * The caller keeps the old text as a backup either way. Where mending does not converge,
 * `salvageProgress` returns null and the caller starts afresh.
 */

export interface Salvaged {
  progress: Progress;
  /** What was left out or replaced, as `path: reason (what was done)` lines in English. */
  notes: string[];
}

/** How many rounds of mending: an event out of order is found only once every event reads. */
const ROUNDS = 5;

/**
 * `input`: parsed JSON that is progress of this version (its kind and version were checked)
 * but may fail the schema. `nowIso`: when the repair happens (a damaged log start becomes this).
 */
export function salvageProgress(input: Record<string, unknown>, nowIso: string): Salvaged | null {
  const draft = structuredClone(input);
  const notes: string[] = [];
  for (let round = 0; round < ROUNDS; round++) {
    const result = progressSchema.safeParse(draft, { error: describeIssue });
    if (result.success) return { progress: result.data, notes };
    const mended = mend(draft, result.error.issues, nowIso);
    if (mended === null) return null;
    notes.push(...mended);
  }
  return null;
}

type Issue = z.core.$ZodIssue;
type Key = PropertyKey;

/**
 * What is done about one issue: the part at `at` is dropped (a list item or a field), set
 * to `value`, or loses the unknown `keys`; `note` says so.
 */
type Fix = { at: readonly Key[]; note: string } & ({ kind: 'drop' } | { kind: 'set'; value: unknown } | { kind: 'keys'; keys: readonly string[] });

/** One round: every issue's part left out or replaced; null when an issue is somewhere no part can be mended. */
function mend(draft: Record<string, unknown>, issues: readonly Issue[], nowIso: string): string[] | null {
  const notes: string[] = [];
  const done: (readonly Key[])[] = [];
  const dropFromLists: (readonly Key[])[] = [];
  let reorder = false;
  for (const issue of issues) {
    if (isOrderIssue(issue)) {
      reorder = true;
      continue;
    }
    const fix = fixFor(draft, issue, nowIso);
    if (fix === null) return null;
    // A part already dropped or replaced this round takes its other issues with it.
    if (done.some((at) => startsWith(fix.at, at))) continue;
    done.push(fix.at);
    notes.push(`${formatIssues([issue])[0] ?? issue.message} (${fix.note})`);
    if (fix.kind === 'drop' && typeof fix.at.at(-1) === 'number') dropFromLists.push(fix.at);
    else apply(draft, fix);
  }
  // List items go after the round, from the back, so that the indices of the others stay right.
  for (const at of dropFromLists.sort((a, b) => Number(b.at(-1)) - Number(a.at(-1)))) {
    const list = valueAt(draft, at.slice(0, -1));
    if (Array.isArray(list)) list.splice(Number(at.at(-1)), 1);
  }
  const log = valueAt(draft, ['log']);
  if (reorder && isRecord(log) && Array.isArray(log.events)) notes.push(...keepInOrder(log));
  return notes;
}

/** The fix for `issue`, by where it is (the list in this file's comment); null where none is possible. */
function fixFor(draft: Record<string, unknown>, issue: Issue, nowIso: string): Fix | null {
  const path = issue.path;
  const [top, second, third] = path;
  if (issue.code === 'unrecognized_keys') return { at: path, kind: 'keys', keys: issue.keys, note: 'left out' };
  switch (top) {
    case 'settings':
      return { at: path.slice(0, 2), kind: 'drop', note: path.length === 1 ? 'default settings' : 'default' };
    case 'sandbox':
    case 'current':
      return { at: [top], kind: 'set', value: null, note: 'left out' };
    case 'epoch':
      return { at: [top], kind: 'drop', note: 'left out' };
    case 'code':
      return typeof second === 'string'
        ? { at: [top, second], kind: 'drop', note: 'code not imported' }
        : { at: [top], kind: 'drop', note: 'code not imported' };
    case 'badges':
      return typeof second === 'number'
        ? { at: [top, second], kind: 'drop', note: 'left out' }
        : { at: [top], kind: 'set', value: [], note: 'badges left out' };
    case 'levels':
      return levelFix(draft, path);
    case 'log':
      if (second === 'startedAt') return { at: path, kind: 'set', value: nowIso, note: 'set to the time of this repair' };
      if (second === 'events' && typeof third === 'number') return { at: path.slice(0, 3), kind: 'drop', note: 'left out' };
      if (second === 'events') return { at: path, kind: 'set', value: [], note: 'events left out' };
      return path.length === 1 ? { at: path, kind: 'set', value: { startedAt: nowIso, events: [] }, note: 'log left out' } : null;
    default:
      return null;
  }
}

/** `levels.<id>…`: the level, one of its tasks, a task's points, `correct` or `stars`, or its hint count. */
function levelFix(draft: Record<string, unknown>, path: readonly Key[]): Fix | null {
  const [, id, part, task, field] = path;
  if (path.length === 1) return { at: path, kind: 'set', value: {}, note: 'levels left out' };
  if (part === 'hintsUsed' && typeof id === 'string') {
    const hints = hintsInLog(draft, id);
    return { at: path, kind: 'set', value: hints, note: `set to the ${hints} hints the log shows` };
  }
  if (part !== 'tasks') return { at: path.slice(0, 2), kind: 'drop', note: 'level left out' };
  if (path.length === 3) return { at: path, kind: 'set', value: {}, note: 'tasks left out' };
  if (field === 'points' && path.length === 5) return { at: path, kind: 'set', value: 0, note: 'worked out again from the level file' };
  if ((field === 'correct' || field === 'stars') && path.length === 5) return { at: path, kind: 'drop', note: 'left out' };
  return task === undefined ? null : { at: path.slice(0, 4), kind: 'drop', note: 'task left out' };
}

function apply(draft: Record<string, unknown>, fix: Fix): void {
  const parent = valueAt(draft, fix.at.slice(0, -1));
  const key = fix.at.at(-1);
  if (fix.kind === 'keys') {
    const target = valueAt(draft, fix.at);
    if (isRecord(target)) for (const unknown of fix.keys) delete target[unknown];
  } else if (isRecord(parent) && typeof key === 'string') {
    if (fix.kind === 'drop') delete parent[key];
    else parent[key] = fix.value;
  }
}

function valueAt(root: unknown, path: readonly Key[]): unknown {
  let value = root;
  for (const key of path) {
    if (Array.isArray(value) && typeof key === 'number') value = value[key];
    else if (isRecord(value) && typeof key === 'string' && Object.hasOwn(value, key)) value = value[key];
    else return undefined;
  }
  return value;
}

function startsWith(path: readonly Key[], prefix: readonly Key[]): boolean {
  return prefix.length <= path.length && prefix.every((key, index) => path[index] === key);
}

/** The log's `hint.shown` events of `level`, the count a merge also trusts (progress-merge.ts). */
function hintsInLog(draft: Record<string, unknown>, level: string): number {
  const events = valueAt(draft, ['log', 'events']);
  if (!Array.isArray(events)) return 0;
  return events.filter((event) => isRecord(event) && event.type === 'hint.shown' && event.level === level).length;
}

/** The schema's "must not be earlier than the event before it" (event-log.ts). */
function isOrderIssue(issue: Issue): boolean {
  const [top, second, , last] = issue.path;
  return issue.code === 'custom' && top === 'log' && second === 'events' && last === 't' && issue.path.length === 4;
}

/**
 * Keeps the longest run of events whose times never go back: one event with a wrong time is
 * left out, not every event after it.
 */
function keepInOrder(log: Record<string, unknown>): string[] {
  const events = log.events as unknown[];
  const times = events.map((event) => (isRecord(event) && typeof event.t === 'number' ? event.t : 0));
  const keep = longestNonDecreasing(times);
  log.events = events.filter((_, index) => keep.has(index));
  return times.flatMap((_, index) => (keep.has(index) ? [] : [`log.events[${index}].t: must not be earlier than the event before it (left out)`]));
}

/** The indices of a longest non-decreasing run in `values` (patience sorting, O(n log n)). */
export function longestNonDecreasing(values: readonly number[]): Set<number> {
  // tails[k]: the index of the smallest last value of a run of length k + 1 found so far.
  const tails: number[] = [];
  const previous: number[] = new Array<number>(values.length).fill(-1);
  values.forEach((value, index) => {
    let low = 0;
    let high = tails.length;
    while (low < high) {
      const middle = (low + high) >> 1;
      if (values[tails[middle]] <= value) low = middle + 1;
      else high = middle;
    }
    if (low > 0) previous[index] = tails[low - 1];
    tails[low] = index;
  });
  const keep = new Set<number>();
  for (let index = tails.at(-1) ?? -1; index >= 0; index = previous[index]) keep.add(index);
  return keep;
}
