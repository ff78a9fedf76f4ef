import { sameBadge, type EarnedBadge } from './badges.ts';
import { HOW_COMPLETED, numberOf, sessionOf, withIds, type EventLogData, type LoggedEvent } from './event-log.ts';
import type { LevelProgress, Progress, TaskRecord } from './progress.ts';

/**
 * Two tabs of the game write the same saved progress. Instead of the last write winning,
 * every write and every tab that hears of another's write merges the two, so that nothing
 * one tab did is lost:
 *
 * - the event log is the union of both logs by event id (event-log.ts), in time order;
 * - a task completed in either tab is completed (the better record when both have it);
 * - a badge earned in either tab is earned (at the earlier time);
 * - hints used: at least what either tab counted and what the merged log shows;
 * - settings, the sandbox scene and the level to resume are working state: `ours` wins.
 *
 * The merge is a union, so merging again changes nothing, and the order of merges does not
 * change which events and tasks end up saved.
 *
 * A reset or an import replaces progress: it gets a new `epoch`, and progress of a later
 * epoch replaces an earlier one instead of merging with it (a tab still holding the old
 * progress must not bring it back).
 */

/** Both merged; the epoch that is later wins outright. */
export function mergeProgress(ours: Progress, theirs: Progress): Progress {
  const [ourEpoch, theirEpoch] = [ours.epoch ?? '', theirs.epoch ?? ''];
  if (theirEpoch > ourEpoch) return theirs;
  if (ourEpoch > theirEpoch) return ours;
  const { log, shiftOurs, shiftTheirs } = mergeLogs(ours.log, theirs.log);
  const levels = mergeLevels(ours.levels, theirs.levels, log.events);
  return { ...ours, levels, badges: mergeBadges(shifted(ours.badges, shiftOurs), shifted(theirs.badges, shiftTheirs)), log };
}

/**
 * Whether `saved` already holds everything of `ours` that a merge keeps: every event (by
 * id), task, badge and hint count. Then a tab that heard of a write has nothing to add, and
 * two tabs never answer each other's writes for ever.
 */
export function holdsAll(saved: Progress, ours: Progress): boolean {
  const [savedEpoch, ourEpoch] = [saved.epoch ?? '', ours.epoch ?? ''];
  if (savedEpoch !== ourEpoch) return savedEpoch > ourEpoch;
  const ids = new Set(withIds(saved.log.events).map((event) => event.id));
  if (!withIds(ours.log.events).every((event) => ids.has(event.id))) return false;
  if (!ours.badges.every((earned) => saved.badges.some((known) => sameBadge(known.badge, earned.badge)))) return false;
  return Object.entries(ours.levels).every(([id, level]) => {
    const kept = saved.levels[id];
    if (!kept || kept.hintsUsed < level.hintsUsed) return false;
    return Object.entries(level.tasks).every(([task, record]) => kept.tasks[task] !== undefined && better(kept.tasks[task], record) === kept.tasks[task]);
  });
}

/**
 * The union of two logs by event id, sorted by time. Logs that started at different times
 * (two tabs that both began with nothing saved) are put on the earlier start's clock;
 * `shiftOurs` / `shiftTheirs` are the milliseconds added to each side's times.
 */
export function mergeLogs(ours: EventLogData, theirs: EventLogData): { log: EventLogData; shiftOurs: number; shiftTheirs: number } {
  const ourStart = Date.parse(ours.startedAt);
  const theirStart = Date.parse(theirs.startedAt);
  const start = Math.min(ourStart, theirStart);
  const shiftOurs = ourStart - start;
  const shiftTheirs = theirStart - start;
  const events = withIds(shiftedEvents(ours.events, shiftOurs));
  const seen = new Set(events.map((event) => event.id));
  for (const event of withIds(shiftedEvents(theirs.events, shiftTheirs))) {
    if (seen.has(event.id)) continue;
    seen.add(event.id);
    events.push(event);
  }
  // Stable: events of one time keep their order, and a session's own events their numbers.
  events.sort((a, b) => a.t - b.t || sameSessionOrder(a, b));
  return { log: { startedAt: ourStart <= theirStart ? ours.startedAt : theirs.startedAt, events }, shiftOurs, shiftTheirs };
}

function sameSessionOrder(a: LoggedEvent, b: LoggedEvent): number {
  if (a.id === undefined || b.id === undefined || sessionOf(a.id) !== sessionOf(b.id)) return 0;
  return numberOf(a.id) - numberOf(b.id);
}

function shiftedEvents(events: readonly LoggedEvent[], shift: number): LoggedEvent[] {
  return shift === 0 ? [...events] : events.map((event) => ({ ...event, t: event.t + shift }));
}

function shifted(badges: readonly EarnedBadge[], shift: number): EarnedBadge[] {
  return shift === 0 ? [...badges] : badges.map((earned) => ({ ...earned, t: earned.t + shift }));
}

function mergeBadges(ours: EarnedBadge[], theirs: EarnedBadge[]): EarnedBadge[] {
  const merged = [...ours];
  for (const earned of theirs) {
    const index = merged.findIndex((known) => sameBadge(known.badge, earned.badge));
    if (index < 0) merged.push(earned);
    else if (earned.t < merged[index].t) merged[index] = earned;
  }
  return merged.sort((a, b) => a.t - b.t);
}

function mergeLevels(
  ours: Record<string, LevelProgress>,
  theirs: Record<string, LevelProgress>,
  events: readonly LoggedEvent[],
): Record<string, LevelProgress> {
  const hintsInLog = new Map<string, number>();
  for (const event of events) if (event.type === 'hint.shown') hintsInLog.set(event.level, (hintsInLog.get(event.level) ?? 0) + 1);
  const merged: Record<string, LevelProgress> = {};
  for (const id of new Set([...Object.keys(ours), ...Object.keys(theirs)])) {
    const [a, b] = [ours[id], theirs[id]];
    const tasks: Record<string, TaskRecord> = { ...a?.tasks };
    for (const [task, record] of Object.entries(b?.tasks ?? {})) tasks[task] = tasks[task] ? better(tasks[task], record) : record;
    merged[id] = { tasks, hintsUsed: Math.max(a?.hintsUsed ?? 0, b?.hintsUsed ?? 0, hintsInLog.get(id) ?? 0) };
  }
  return merged;
}

/** The record with more points; on a tie the learner's own work (done, then shown, then skipped); `a` if still tied. */
function better(a: TaskRecord, b: TaskRecord): TaskRecord {
  if (a.points !== b.points) return a.points > b.points ? a : b;
  return HOW_COMPLETED.indexOf(a.how) <= HOW_COMPLETED.indexOf(b.how) ? a : b;
}
