import { describe, expect, it } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { checkGoal, NO_EVENTS, tallyAction, touchesGoal } from '../../src/quest/goal-check.ts';
import { goalSchema, kindOfGoal } from '../../src/quest/goal.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';

const goal = goalSchema.parse({
  code: {
    lab: 'ray-sphere',
    function: 'hitSphere',
    signature: 'hitSphere(origin, direction, center, radius)',
    contract: { en: 'The nearest t > 0, or null.', nl: 'De dichtstbijzijnde t > 0, of null.' },
    skeleton: 'function hitSphere(origin, direction, center, radius) {}',
    cases: { edges: ['tangent', 'inside-sphere'], random: 100, seed: 43 },
  },
});
const state = initialState(defaultScene());
const graded = (passed: number, lab = 'ray-sphere'): LabAction => ({ type: 'code.graded', lab, passed, total: 102, failed: passed === 102 ? null : 'tangent' });

describe('a code lab goal', () => {
  it('is something done in the lab', () => {
    expect(goal.kind).toBe('code');
    expect(kindOfGoal(goal)).toBe('do');
  });

  it('is met by the first run that passes every case, not by one that fails a case', () => {
    const failed = tallyAction(goal, NO_EVENTS, state, graded(101));
    expect(checkGoal(goal, state, failed)).toBe(false);
    expect(checkGoal(goal, state, tallyAction(goal, failed, state, graded(102)))).toBe(true);
  });

  it('counts only runs of its own lab, each run a try at it', () => {
    expect(checkGoal(goal, state, tallyAction(goal, NO_EVENTS, state, graded(102, 'mirror')))).toBe(false);
    expect(touchesGoal(goal, state, state, graded(3))).toBe(true);
    expect(touchesGoal(goal, state, state, graded(3, 'mirror'))).toBe(false);
  });

  it('refuses an edge case its lab does not know', () => {
    const json = {
      code: {
        lab: 'ray-sphere',
        function: 'hitSphere',
        signature: 's',
        contract: 'c',
        skeleton: 'k',
        cases: { edges: ['backwards'], random: 1, seed: 1 },
      },
    };
    expect(goalSchema.safeParse(json).success).toBe(false);
    json.code.cases.edges = ['tangent'];
    expect(goalSchema.safeParse(json).success).toBe(true);
  });
});
