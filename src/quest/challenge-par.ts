import { z } from 'zod';
import { wholeNumberIn } from '../scene/scene-schema-parts.ts';

/**
 * The golf score of a match-the-target challenge (spec/challenges.md §2): stars for matching
 * with few renders, few changes or few rays, against the level's par, as Learn Git Branching
 * scores a level by its command count. One kind of par per challenge, so the rule shown
 * before the start names one number.
 */

/** What a par counts: the learner's renders, their changes of the editable settings, or the rays their renders traced. */
export const PAR_KINDS = ['renders', 'changes', 'rays'] as const;
export type ParKind = (typeof PAR_KINDS)[number];

/** A challenge's par as the app reads it: which count, and how many for three stars. */
export interface ChallengePar {
  kind: ParKind;
  limit: number;
}

/** What the lab has counted since the challenge started (each render compared, each change of the scene, each ray of the learner's renders). */
export interface ChallengeCounts {
  renders: number;
  changes: number;
  rays: number;
}

export type Stars = 1 | 2 | 3;

export const starsSchema = z.union([z.literal(1), z.literal(2), z.literal(3)]);

/** The counts as fields of an action (challenge.compared). */
export const challengeCountsShape = { renders: z.int().min(1), changes: z.int().min(0), rays: z.int().min(0) };

/** The counts in a logged event: logs from before they were counted lack them. */
export const optionalCounts = {
  renders: challengeCountsShape.renders.optional(),
  changes: challengeCountsShape.changes.optional(),
  rays: challengeCountsShape.rays.optional(),
};

/**
 * `{ "renders": 3 }`, `{ "changes": 4 }` or `{ "rays": 2000000 }` in a level file. Rays: a
 * 320 × 240 render at one sample and no bounces already traces about 77 000 camera rays.
 */
export const challengeParSchema = z
  .union([
    z.strictObject({ renders: wholeNumberIn([1, 50]).describe('Renders for three stars.') }),
    z.strictObject({ changes: wholeNumberIn([1, 50]).describe('Changes of the editable settings for three stars.') }),
    z.strictObject({ rays: wholeNumberIn([1000, 1e10]).describe("Rays traced by the learner's renders, in all, for three stars.") }),
  ])
  .describe('Three stars at or under par, two up to 1.5 times par (rounded down), one for any match.')
  .transform(parOf);

function parOf(par: { renders: number } | { changes: number } | { rays: number }): ChallengePar {
  if ('renders' in par) return { kind: 'renders', limit: par.renders };
  if ('changes' in par) return { kind: 'changes', limit: par.changes };
  return { kind: 'rays', limit: par.rays };
}

/** The count the par is about. */
export function countFor(kind: ParKind, counts: ChallengeCounts): number {
  switch (kind) {
    case 'renders':
      return counts.renders;
    case 'changes':
      return counts.changes;
    case 'rays':
      return counts.rays;
    default: {
      const never: never = kind;
      return never;
    }
  }
}

/** The most for two stars: 1.5 × par, rounded down (the rule the panel shows before the start). */
export function twoStarLimit(par: ChallengePar): number {
  return Math.floor(par.limit * 1.5);
}

/** Stars for a match with these counts: 3 at or under par, 2 within 1.5 × par, else 1. */
export function challengeStars(counts: ChallengeCounts, par: ChallengePar): Stars {
  const count = countFor(par.kind, counts);
  if (count <= par.limit) return 3;
  if (count <= twoStarLimit(par)) return 2;
  return 1;
}

/**
 * A matched challenge's points (docs/levels.md "Points, badges and the gate"): the task's
 * points times stars / 3, rounded, so ★★★ earns them all and every match earns some.
 */
export function pointsForStars(points: number, stars: Stars): number {
  return Math.round((points * stars) / 3);
}

/** "★★☆": earned stars filled, the rest hollow. */
export function starText(stars: Stars): string {
  return '★'.repeat(stars) + '☆'.repeat(3 - stars);
}
