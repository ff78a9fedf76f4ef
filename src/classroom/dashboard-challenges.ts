import { MATCH_SCORE } from '../quest/challenge-closeness.ts';
import type { Stars } from '../quest/challenge-par.ts';
import { bestScore } from './challenge-attempt.ts';
import type { ClassRecord } from './dashboard-record.ts';
import type { TaskAttempt } from './task-attempts.ts';

/**
 * How close a class got in each challenge (spec/challenges.md §3), from the task attempts
 * (themselves read from the raw events, task-attempts.ts): per learner their best match
 * score over all their attempts; for those who matched it themselves, their stars; for those
 * who did not, where they stopped (the score of their last render). No ranking of learners:
 * the teacher sees the class's spread, each learner's score stays their own.
 */

export interface ChallengeSummary {
  level: string;
  task: string;
  /** Learners who rendered at least once in the challenge. */
  learners: number;
  /** Each of those learners' best match score (0–100), lowest first. */
  bestScores: number[];
  /** Learners who matched it themselves (not by "Show me"). */
  matched: number;
  /** Matched learners by their best stars: [★, ★★, ★★★]. */
  stars: [number, number, number];
  /** Learners who never matched it (themselves or shown): the score of their last render, lowest first. */
  stoppedAt: number[];
}

/** Every challenge some learner rendered in, in the order first met. */
export function summarizeChallenges(records: readonly ClassRecord[]): ChallengeSummary[] {
  const keys = new Map<string, { level: string; task: string }>();
  for (const record of records) for (const attempt of record.attempts) if (attempt.challenge) keys.set(`${attempt.level}\u0000${attempt.task}`, attempt);
  return [...keys.values()].map(({ level, task }) => {
    const learners = records
      .map((record) => record.attempts.filter((attempt) => attempt.level === level && attempt.task === task))
      .filter((attempts) => attempts.some((attempt) => attempt.challenge && attempt.challenge.renders > 0));
    const summary: ChallengeSummary = { level, task, learners: learners.length, bestScores: [], matched: 0, stars: [0, 0, 0], stoppedAt: [] };
    for (const attempts of learners) {
      const best = bestOf(attempts);
      if (best !== null) summary.bestScores.push(best);
      const stars = bestStars(attempts);
      if (attempts.some((attempt) => attempt.how === 'done')) summary.matched++;
      if (stars !== null) summary.stars[stars - 1]++;
      if (!attempts.some((attempt) => attempt.how === 'done' || attempt.how === 'shown')) {
        const last = attempts.findLast((attempt) => attempt.challenge && attempt.challenge.scores.length > 0)?.challenge?.scores.at(-1);
        if (last !== undefined) summary.stoppedAt.push(last);
      }
    }
    summary.bestScores.sort((a, b) => a - b);
    summary.stoppedAt.sort((a, b) => a - b);
    return summary;
  });
}

function bestOf(attempts: readonly TaskAttempt[]): number | null {
  const scores = attempts.map((attempt) => bestScore(attempt.challenge)).filter((score): score is number => score !== null);
  return scores.length === 0 ? null : Math.max(...scores);
}

function bestStars(attempts: readonly TaskAttempt[]): Stars | null {
  const stars = attempts.map((attempt) => attempt.challenge?.stars ?? null).filter((value): value is Stars => value !== null);
  return stars.length === 0 ? null : (Math.max(...stars) as Stars);
}

/** How many of the best scores reach a match (75 or more). */
export function reachedMatch(summary: ChallengeSummary): number {
  return summary.bestScores.filter((score) => score >= MATCH_SCORE).length;
}
