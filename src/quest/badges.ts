import { z } from 'zod';
import { ID_MAX } from './kebab-id.ts';

const id = () => z.string().max(ID_MAX);

/**
 * Badges for milestones (spec: first render, all mandatory tasks of a chapter, no hints used
 * in a level, a sandbox scene saved…). Each kind names what it was earned for, so the UI
 * can word it in the learner's language; a level's own badges (its `badges` field) have
 * their titles in the level file.
 */
export const badgeSchema = z.discriminatedUnion('kind', [
  z.strictObject({ kind: z.literal('first-render') }),
  z.strictObject({ kind: z.literal('sandbox-saved') }),
  /** Every mandatory task of every playable level of the chapter. */
  z.strictObject({ kind: z.literal('chapter-done'), chapter: id() }),
  /** A level passed without opening any hint (text, guidance or show-me); an offer left alone does not count. */
  z.strictObject({ kind: z.literal('no-hints'), level: id() }),
  /** Every task of a level, optional ones too, done by the learner (not shown, not skipped). */
  z.strictObject({ kind: z.literal('every-task'), level: id() }),
  /** One of a level's own badges. */
  z.strictObject({ kind: z.literal('level-badge'), level: id(), badge: id() }),
]);

export type Badge = z.output<typeof badgeSchema>;

export const earnedBadgeSchema = z.strictObject({ badge: badgeSchema, t: z.number().min(0).describe("When, on the event log's clock.") });
export type EarnedBadge = z.output<typeof earnedBadgeSchema>;

/** Badges are earned once: two are the same when they are of the same kind for the same thing. */
export function sameBadge(a: Badge, b: Badge): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}
