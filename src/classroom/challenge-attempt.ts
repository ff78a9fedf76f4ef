import type { Stars } from '../quest/challenge-par.ts';
import type { LoggedEvent } from '../quest/event-log.ts';

/**
 * A challenge task's tries within one attempt, read from its `challenge.compared` events
 * (spec/challenges.md §3: renders, changes, closeness at each render, stars). The counts are
 * the lab's since the challenge started (the level's scene loaded), as the learner saw them.
 */
export interface ChallengeTries {
  /** Renders compared in this attempt. */
  renders: number;
  /** Changes of the editable settings up to the last render compared. */
  changes: number;
  /** Rays the learner's renders traced, up to the last render compared. */
  rays: number;
  /** The match score (0–100, 75 a match: challenge-closeness.ts) of each render, in order. */
  scores: number[];
  /** The golf score of a match by the learner; null when not matched (or matched by "show me"). */
  stars: Stars | null;
}

type Comparison = Extract<LoggedEvent, { type: 'challenge.compared' }>;

/** The tries with one more comparison: counts as the event gives them, its score added. */
export function addComparison(tries: ChallengeTries | undefined, event: Comparison): ChallengeTries {
  const before = tries ?? { renders: 0, changes: 0, rays: 0, scores: [], stars: null };
  return {
    renders: before.renders + 1,
    changes: event.changes ?? before.changes,
    rays: event.rays ?? before.rays,
    scores: event.score === undefined ? before.scores : [...before.scores, event.score],
    stars: before.stars,
  };
}

/** The best score of the tries (null when none was scored). */
export function bestScore(tries: ChallengeTries | undefined): number | null {
  return tries && tries.scores.length > 0 ? Math.max(...tries.scores) : null;
}
