import { z } from 'zod';
import { sceneSchema } from '../scene/scene-schema.ts';
import type { Scene } from '../scene/scene.ts';
import { earnedBadgeSchema } from './badges.ts';
import { eventLogSchema, HOW_COMPLETED, newEventLogData, type QuestClock } from './event-log.ts';
import { LOCALES } from './localized-text.ts';

/**
 * Everything a learner has achieved, saved between visits (progress-store.ts) and exported
 * as a file. Points are not stored: they are the sum over the completed tasks, so the two
 * can never disagree.
 */

/** Marks our files among all JSON a learner might pick by mistake. */
export const PROGRESS_KIND = 'ray-tracer-quest-progress';
export const PROGRESS_VERSION = 1;

const taskRecordSchema = z.strictObject({
  how: z.enum(HOW_COMPLETED),
  points: z.number().min(0),
  /** Quiz tasks only: whether the prediction was right. */
  correct: z.boolean().optional(),
});
export type TaskRecord = z.output<typeof taskRecordSchema>;

const levelProgressSchema = z.strictObject({
  /** The completed tasks by id. */
  tasks: z.record(z.string(), taskRecordSchema),
  /** Hint rungs shown in this level (for the no-hints badge). */
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
  levels: z.record(z.string(), levelProgressSchema),
  badges: z.array(earnedBadgeSchema),
  settings: settingsSchema.prefault({}),
  /** The sandbox level's saved scene. */
  sandbox: savedScene.nullable(),
  /** The level being played and its scene as the learner left it, to resume after a reload. */
  current: z.strictObject({ level: z.string(), scene: savedScene }).nullable(),
  log: eventLogSchema,
});

export type Progress = z.output<typeof progressSchema>;

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
