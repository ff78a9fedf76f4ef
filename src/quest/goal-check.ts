import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import { compare, conditionHolds } from './condition.ts';
import { goalParts, type EventGoal, type Goal, type QuizGoal } from './goal.ts';
import { readPath } from './state-path.ts';

/**
 * Whether a goal is met. A state goal is met while the state holds ("supersampling is at
 * least 2"); an event goal once its action has happened since the task was shown ("the
 * view was orbited"), which needs memory when goals are combined: "orbit and zoom" is met
 * when the second of the two happens. That memory is the tally, a count per event goal,
 * kept by the caller (the quest engine, per task) so that these functions stay pure.
 */

/** How often each event goal inside a task's goal has matched since the task was shown. */
export type EventTally = ReadonlyMap<EventGoal, number>;

export const NO_EVENTS: EventTally = new Map();

/** The tally after `action`, which left the app in `state`: every event goal it matches counts once more. */
export function tallyAction(goal: Goal, tally: EventTally, state: LabState, action: LabAction): EventTally {
  let next: Map<EventGoal, number> | undefined;
  for (const { goal: part } of goalParts(goal)) {
    if (!('event' in part) || !eventMatches(part, state, action)) continue;
    next ??= new Map(tally);
    next.set(part, (next.get(part) ?? 0) + 1);
  }
  return next ?? tally;
}

/** The action is the goal's event, with the goal's `with` fields, leaving the state as `where` says. */
export function eventMatches(goal: EventGoal, state: LabState, action: LabAction): boolean {
  if (action.type !== goal.event) return false;
  const holds = (root: unknown, conditions: EventGoal['where']) =>
    Object.entries(conditions ?? {}).every(([path, condition]) => conditionHolds(readPath(root, path), condition));
  return holds(action, goal.with) && holds(state, goal.where);
}

/**
 * Whether the goal is met in `state`, given the events tallied since its task was shown.
 * Quiz and info goals are never met here: they complete through the quest engine's
 * `answerQuiz` and `next`.
 */
export function checkGoal(goal: Goal, state: LabState, tally: EventTally): boolean {
  if ('event' in goal) return (tally.get(goal) ?? 0) >= (goal.times ?? 1);
  if ('state' in goal) return compare(readPath(state, goal.state), goal.op, goal.value);
  if ('all' in goal) return goal.all.every((part) => checkGoal(part, state, tally));
  if ('any' in goal) return goal.any.some((part) => checkGoal(part, state, tally));
  return false;
}

/**
 * Whether `action` is a step towards `goal`: it is one of the goal's events, or it changed
 * a value one of its state goals looks at. Used to time an optional task from the learner's
 * first move towards it rather than from the moment its level opened.
 */
export function touchesGoal(goal: Goal, before: LabState | null, state: LabState, action: LabAction): boolean {
  return goalParts(goal).some(({ goal: part }) => {
    if ('event' in part) return action.type === part.event;
    if ('state' in part) return before !== null && readPath(before, part.state) !== readPath(state, part.state);
    return false;
  });
}

/** Whether `choice` (a position in the quiz's choices) is the right answer. */
export function isRightAnswer(goal: QuizGoal, choice: number): boolean {
  return choice === goal.quiz.answer;
}
