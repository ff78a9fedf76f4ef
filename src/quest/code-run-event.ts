import type { LabAction } from '../lab-state/lab-action.ts';
import type { QuestEvent } from './event-log.ts';
import type { Level } from './level-schema.ts';

/**
 * A code lab's run as logged (issue 43: "runs, failing case kinds … in the exports"): the
 * grade the panel reported, with the open level and its code task for that lab, so that the
 * classroom reads each run into the task's attempt (classroom/code-lab-attempt.ts).
 */
export function codeRunEvent(level: Level | null, action: Extract<LabAction, { type: 'code.graded' }>): QuestEvent {
  const { lab, passed, total, failed } = action;
  const event = { type: 'code.graded' as const, level: level?.id ?? null, lab, passed, total, failed };
  const task = level?.tasks.find((candidate) => candidate.goal.kind === 'code' && candidate.goal.code.lab === lab);
  return task ? { ...event, task: task.id } : event;
}
