import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import { compare, conditionHolds, type JsonValue } from './condition.ts';
import { goalParts, predictionParts, type ChallengeGoal, type CodeGoal, type EventGoal, type Goal, type PredictionGoal } from './goal.ts';
import { readPath } from './state-path.ts';

/**
 * Whether a goal is met. A state goal is met while the state holds ("supersampling is at
 * least 2"); an event goal once its action has happened since the task was shown ("the
 * view was orbited"), which needs memory when goals are combined: "orbit and zoom" is met
 * when the second of the two happens. That memory is the tally, a count per event goal,
 * kept by the caller (the quest engine, per task) so that these functions stay pure.
 */

/**
 * How often each event goal (or challenge: each close render; code lab: each run that
 * passed every case) inside a task's goal has matched since the task was shown.
 */
export type EventTally = ReadonlyMap<TalliedGoal, number>;
type TalliedGoal = EventGoal | ChallengeGoal | CodeGoal;

export const NO_EVENTS: EventTally = new Map();

/** The tally after `action`, which left the app in `state`: every event goal it matches counts once more. */
export function tallyAction(goal: Goal, tally: EventTally, state: LabState, action: LabAction): EventTally {
  let next: Map<TalliedGoal, number> | undefined;
  for (const { goal: part } of goalParts(goal)) {
    if (part.kind !== 'event' && part.kind !== 'challenge' && part.kind !== 'code') continue;
    const matches =
      part.kind === 'event' ? eventMatches(part, state, action) : part.kind === 'challenge' ? isCloseEnough(part, action) : allPassed(part, action);
    if (!matches) continue;
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

/** The action reports a comparison of the challenge's pictures within its threshold. */
function isCloseEnough(goal: ChallengeGoal, action: LabAction): boolean {
  return action.type === 'challenge.compared' && action.difference <= goal.challenge.measure.threshold;
}

/** The action reports a run of the lab's function that passed every case. */
function allPassed(goal: CodeGoal, action: LabAction): boolean {
  return action.type === 'code.graded' && action.lab === goal.code.lab && action.passed === action.total;
}

/**
 * Whether the goal is met in `state`, given the events tallied since its task was shown.
 * Quiz, estimate and info goals are never met here: they complete through the quest
 * engine's `predict` and `next`.
 */
export function checkGoal(goal: Goal, state: LabState, tally: EventTally): boolean {
  switch (goal.kind) {
    case 'event':
      return (tally.get(goal) ?? 0) >= (goal.times ?? 1);
    case 'challenge':
    case 'code':
      return (tally.get(goal) ?? 0) >= 1;
    case 'state':
      return compare(readPath(state, goal.state), goal.op, goal.value);
    case 'all':
      return goal.all.every((part) => checkGoal(part, state, tally));
    case 'any':
      return goal.any.some((part) => checkGoal(part, state, tally));
    case 'quiz':
    case 'estimate':
    case 'picture':
    case 'info':
      return false;
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/**
 * Whether `action` is a step towards `goal`: it is one of the goal's events with the goal's
 * `with` fields (selecting pixel 3,1 is no step towards "select pixel 0,0"), or it changed
 * a value one of its state goals looks at. Used to time an optional task from the learner's
 * first move towards it rather than from the moment its level opened, so a task nobody
 * touched has no attempt in the exports.
 *
 * Values are compared by content, not by reference: the store rebuilds the scene on every
 * edit, so painting the ball gives the box a new but equal object, and that is no change.
 * `where` is left out on purpose: it says what the action must leave behind to complete
 * the goal, and a move that does not get there yet is still a move towards it.
 */
export function touchesGoal(goal: Goal, before: LabState | null, state: LabState, action: LabAction): boolean {
  return goalParts(goal).some(({ goal: part }) => {
    switch (part.kind) {
      case 'event':
        return eventMatches({ ...part, where: undefined }, state, action);
      case 'state':
        return before !== null && !sameContent(readPath(before, part.state), readPath(state, part.state));
      // Every render of a challenge is a try at it, close or not.
      case 'challenge':
        return action.type === 'challenge.compared';
      // Every run of a code lab is a try at it, passed or not.
      case 'code':
        return action.type === 'code.graded' && action.lab === part.code.lab;
      // A combination is a step towards it through its parts, which goalParts lists too.
      case 'all':
      case 'any':
      case 'quiz':
      case 'estimate':
      case 'picture':
      case 'info':
        return false;
      default: {
        const never: never = part;
        return never;
      }
    }
  });
}

/** Whether two values read from the state hold the same content (numbers within the goals' tolerance). */
function sameContent(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  // A value that is not there equals nothing in `compare`, but two absences are no change.
  if (a === undefined || b === undefined) return false;
  return compare(a, '==', b as JsonValue);
}

/** A prediction as the learner gives it: a position in a quiz's choices, or a number. */
export type Prediction = { choice: number } | { value: number };

/** Whether the prediction is right: the quiz's answer, or a number within the estimate's tolerance. */
export function isRightPrediction(goal: PredictionGoal, prediction: Prediction): boolean {
  switch (goal.kind) {
    case 'quiz':
    case 'picture':
      return 'choice' in prediction && prediction.choice === predictionParts(goal).answer;
    case 'estimate':
      // A little slack for the decimal the learner typed (0.1 + 0.2 is not 0.3 in binary).
      return 'value' in prediction && Math.abs(prediction.value - goal.estimate.answer) <= goal.estimate.tolerance + 1e-9;
    default: {
      const never: never = goal;
      return never;
    }
  }
}

/** Whether a prediction fits the goal's form (a choice for a quiz, a finite number for an estimate). */
export function fitsGoal(goal: PredictionGoal, prediction: Prediction): boolean {
  switch (goal.kind) {
    case 'quiz':
    case 'picture':
      return 'choice' in prediction && Number.isInteger(prediction.choice) && prediction.choice >= 0 && prediction.choice < predictionParts(goal).choices;
    case 'estimate':
      return 'value' in prediction && Number.isFinite(prediction.value);
    default: {
      const never: never = goal;
      return never;
    }
  }
}
