import type { LabAction } from '../lab-state/lab-action.ts';
import type { ActiveLevel } from './active-level.ts';
import { matchScore } from './challenge-closeness.ts';
import type { QuestEvent } from './event-log.ts';

/**
 * A comparison as logged: with the counts, and the open level's challenge task and the match
 * score its learner read (challenge-closeness.ts), so a teacher sees how close each try came.
 */
export function comparisonEvent(active: ActiveLevel | null, action: Extract<LabAction, { type: 'challenge.compared' }>): QuestEvent {
  const { difference, renders, changes, rays } = action;
  const event = { type: 'challenge.compared' as const, level: active?.level.id ?? null, difference, renders, changes, rays };
  const task = active?.level.tasks.find((candidate) => active.tallies.has(candidate.id) && candidate.goal.kind === 'challenge');
  if (task?.goal.kind !== 'challenge') return event;
  return { ...event, task: task.id, score: matchScore(difference, task.goal.challenge.measure.threshold) };
}
