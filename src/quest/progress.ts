import { z } from 'zod';
import { sceneSchema } from '../scene/scene-schema.ts';
import type { Scene } from '../scene/scene.ts';
import { earnedBadgeSchema } from './badges.ts';
import { starsSchema } from './challenge-par.ts';
import { eventLogSchema, HOW_COMPLETED, newEventLogData, randomSessionId, type QuestClock } from './event-log.ts';
import { ID_MAX } from './kebab-id.ts';
import { LOCALES } from './localized-text.ts';
import { labCodeSchema } from './progress-lab-code.ts';

/**
 * Everything a learner has achieved, saved between visits (progress-store.ts) and exported
 * as a file. Points are not stored: they are the sum over the completed tasks, so the two
 * can never disagree.
 */

/** Level and task ids as keys: short, so that no message quotes a huge one. */
const idKey = () => z.string().min(1).max(ID_MAX);

/** Marks our files among all JSON a learner might pick by mistake. */
export const PROGRESS_KIND = 'ray-tracer-quest-progress';
export const PROGRESS_VERSION = 1;

/** An ISO 8601 time and a random tail (newEpoch): epochs compare as text in time order. */
const EPOCH = /^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z\.[a-z0-9]{1,16}$/;

const taskRecordSchema = z.strictObject({
  how: z.enum(HOW_COMPLETED),
  /** Read as saved, then recomputed from the level files (progress-reconcile.ts): never trusted. */
  points: z.number().min(0),
  /** Quiz tasks only: whether the prediction was right. */
  correct: z.boolean().optional(),
  /** Challenge tasks matched by the learner (saves from issue 41 on): the golf score, which sets the points (scoring.ts). */
  stars: starsSchema.optional(),
});
export type TaskRecord = z.output<typeof taskRecordSchema>;

const levelProgressSchema = z.strictObject({
  /** The completed tasks by id. */
  tasks: z.record(idKey(), taskRecordSchema),
  /**
   * Hint rungs the learner opened in this level (for the no-hints badge); an offer after idle
   * time counts only once opened. Progress saved before offers existed also counted the
   * rungs shown by themselves after idle time (event-log.ts HINT_TRIGGERS): it keeps them.
   */
  hintsUsed: z.number().int().min(0),
});
export type LevelProgress = z.output<typeof levelProgressSchema>;

// Settings get defaults so that a setting added later does not make older progress unreadable.
const settingsSchema = z.strictObject({
  locale: z.enum(LOCALES).default('en'),
  colorBlindPalette: z.boolean().default(false),
});
export type QuestSettings = z.output<typeof settingsSchema>;

/** A saved scene, typed as the app's Scene (whose mesh names are plain strings). */
const savedScene = sceneSchema.transform((scene): Scene => scene);

export const progressSchema = z.strictObject({
  kind: z.literal(PROGRESS_KIND),
  version: z.literal(PROGRESS_VERSION),
  levels: z.record(idKey(), levelProgressSchema),
  badges: z.array(earnedBadgeSchema),
  settings: settingsSchema.prefault({}),
  /** The sandbox level's saved scene. */
  sandbox: savedScene.nullable(),
  /** The level being played and its scene as the learner left it, to resume after a reload. */
  current: z.strictObject({ level: idKey(), scene: savedScene }).nullable(),
  log: eventLogSchema,
  /** Exported files only (from issue 43 on): the learner's code per code lab (progress-lab-code.ts). */
  code: labCodeSchema,
  /**
   * Set by a reset or an import, which replace the progress rather than add to it: tabs
   * merge progress of the same epoch and give way to a later one (progress-merge.ts).
   * Absent in progress that was never replaced.
   */
  epoch: z.string().regex(EPOCH).optional(),
});

export type Progress = z.output<typeof progressSchema>;

/**
 * The epoch of progress that replaces progress of epoch `before` at `wallMs`: its time is
 * at least a millisecond after `before`'s, so that it compares later even when the clock
 * has not moved (or was set back); the random tail tells apart two tabs' epochs.
 */
export function newEpoch(wallMs: number, before: string | undefined, random = randomSessionId()): string {
  const after = before === undefined ? Number.NEGATIVE_INFINITY : Date.parse(before.slice(0, before.lastIndexOf('.'))) + 1;
  return `${new Date(Math.max(wallMs, after)).toISOString()}.${random}`;
}

export function newProgress(clock: QuestClock): Progress {
  return {
    kind: PROGRESS_KIND,
    version: PROGRESS_VERSION,
    levels: {},
    badges: [],
    settings: settingsSchema.parse({}),
    sandbox: null,
    current: null,
    log: newEventLogData(clock),
  };
}

export function pointsOf(progress: Progress): number {
  let points = 0;
  for (const level of Object.values(progress.levels)) for (const task of Object.values(level.tasks)) points += task.points;
  return points;
}
