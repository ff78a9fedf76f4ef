import { z } from 'zod';
import { kebabId } from '../quest/kebab-id.ts';
import type { KeyValueStorage } from '../quest/saved-backups.ts';
import type { LevelSummary } from './dashboard-summary.ts';

/**
 * Typical minutes per level as a class really took them, for the teacher page (issue 40:
 * "typical minutes from the median active time when known"). Whenever the dashboard has
 * results loaded, it keeps here, per level, the median active time of the learners who passed
 * it (dashboard-summary.ts: the level's visits with the tab visible) and how many learners
 * that median is of. Only these two numbers per level are kept: no code, no file, no single
 * learner's time beyond what a median of one is. A level the latest files do not have keeps
 * the figure it had, so a teacher who loads lesson 2's files does not lose lesson 1's.
 *
 * The median is of whole levels as the learners' own assignments required them; the teacher
 * page shows it next to the estimate's tasks, so a different choice of required tasks makes
 * it a guide rather than a promise (docs/classroom.md says so).
 */

export const MEASURED_MINUTES_KEY = 'rtq.teacher.measured-minutes';

export interface MeasuredLevel {
  /** The median active time of the learners who passed the level, in minutes. */
  minutes: number;
  /** How many learners passed it: the median is of their times. */
  learners: number;
}

export type MeasuredMinutes = Record<string, MeasuredLevel>;

const storedSchema = z.strictObject({
  version: z.literal(1),
  levels: z.record(kebabId(), z.strictObject({ minutes: z.number().nonnegative(), learners: z.number().int().positive() })),
});

/** Per level that some learner passed: the median of their active minutes, and how many they were. */
export function measuredMinutes(levels: readonly LevelSummary[]): MeasuredMinutes {
  return Object.fromEntries(
    levels.flatMap((level) => (level.stats ? [[level.level, { minutes: level.stats.median / 60_000, learners: level.stats.count }]] : [])),
  );
}

/** What the dashboard kept in this browser; nothing when it kept nothing, or what it kept cannot be read. */
export function readMeasuredMinutes(storage: KeyValueStorage): MeasuredMinutes {
  try {
    const parsed = storedSchema.safeParse(JSON.parse(storage.getItem(MEASURED_MINUTES_KEY) ?? 'null'));
    return parsed.success ? parsed.data.levels : {};
  } catch {
    // Unreadable or refused storage: the teacher page shows its estimates, as before any class.
    return {};
  }
}

/** Keeps `measured` over what was kept for the same levels; whether the browser stored it. */
export function keepMeasuredMinutes(storage: KeyValueStorage, measured: MeasuredMinutes): boolean {
  if (Object.keys(measured).length === 0) return true;
  try {
    storage.setItem(MEASURED_MINUTES_KEY, JSON.stringify({ version: 1, levels: { ...readMeasuredMinutes(storage), ...measured } }));
    return true;
  } catch {
    // Full or refused storage: the page still shows the figures; only the teacher page's guide is not updated.
    return false;
  }
}
