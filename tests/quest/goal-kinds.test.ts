import { issueLine } from '../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { checkGoal, NO_EVENTS, tallyAction, touchesGoal } from '../../src/quest/goal-check.ts';
import { children, GOAL_KINDS, goalParts, goalSchema, type Goal } from '../../src/quest/goal.ts';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { levelFile } from '../support/quest-fixtures.ts';

/**
 * Goal kinds are one tagged union: a level file's `{ "event": … }` is parsed into
 * `{ kind: 'event', … }`, every place that tells kinds apart switches on `kind` with a default
 * the compiler proves unreachable, and every walk through nested goals goes through
 * `children`. These tests show both: a switch that forgets a kind does not compile, and each
 * walker reaches a goal however deep it is nested.
 */

const goal = (json: unknown): Goal => goalSchema.parse(json);

/** One goal of each kind, as a level file writes it. */
const EXAMPLES: Record<string, unknown> = {
  event: { event: 'view.orbited' },
  state: { state: 'scene.settings.supersampling', op: '>=', value: 2 },
  all: { all: [{ event: 'view.orbited' }] },
  any: { any: [{ event: 'view.zoomed' }] },
  quiz: { quiz: { question: 'Which?', choices: ['a', 'b'], answer: 0 } },
  estimate: { estimate: { question: 'How far?', answer: 5, tolerance: 0.5 } },
  picture: { picture: { question: 'Which picture?', choices: [{ actions: [{ type: 'view.orbited' }] }, { actions: [{ type: 'view.zoomed' }] }], answer: 1 } },
  challenge: {
    challenge: {
      target: [{ type: 'settings.changed', changes: { shadows: false } }],
      editable: ['tracer.shadows'],
      measure: { threshold: 0.01 },
      par: { renders: 2 },
    },
  },
  code: {
    code: {
      lab: 'ray-sphere',
      function: 'hitSphere',
      signature: 'hitSphere(origin, direction, center, radius)',
      contract: 'The nearest t > 0, or null.',
      skeleton: 'function hitSphere(origin, direction, center, radius) {}',
      cases: { edges: ['tangent'], random: 10, seed: 1 },
    },
  },
  info: { info: true },
};

describe('goal kinds', () => {
  it('are tagged at load by the field that marks them in the file, one kind per field', () => {
    expect(Object.keys(EXAMPLES).sort()).toEqual([...GOAL_KINDS].sort());
    for (const [field, json] of Object.entries(EXAMPLES)) expect(goal(json).kind, field).toBe(field);
    expect(goal({ info: true })).toEqual({ kind: 'info' });
    // The tag is the parser's, not the author's: a file that writes one is refused.
    expect(goalSchema.safeParse({ kind: 'event', event: 'view.orbited' }).success).toBe(false);
  });

  it('are told apart by switches the compiler checks: one that forgets a kind does not compile', () => {
    // `npx tsc --noEmit` type-checks this file. Were `kind` not a closed union of literals (or the
    // case for "any" present), `goal` would be `never` in the default and the directive below
    // would itself be the error.
    function describeWithoutAny(part: Goal): string {
      switch (part.kind) {
        case 'event':
        case 'state':
        case 'all':
        case 'quiz':
        case 'estimate':
        case 'picture':
        case 'challenge':
        case 'info':
          return part.kind;
        default: {
          // @ts-expect-error: an "any" goal reaches here, and it is not `never`.
          const never: never = part;
          return `forgotten: ${(never as Goal).kind}`;
        }
      }
    }
    expect(describeWithoutAny(goal(EXAMPLES.any))).toBe('forgotten: any');
    expect(describeWithoutAny(goal(EXAMPLES.all))).toBe('all');
  });
});

describe('walking nested goals', () => {
  // Depth 0 any → 1 all → 2 any → 3 all → 4 event/state, beside shallower leaves.
  const deep = goal({
    any: [
      {
        all: [
          { event: 'view.zoomed' },
          {
            any: [
              {
                all: [
                  { event: 'view.orbited', times: 2 },
                  { state: 'scene.settings.supersampling', op: '>=', value: 2 },
                ],
              },
            ],
          },
        ],
      },
      { state: 'scene.settings.shadows', op: '==', value: false },
    ],
  });
  const start = initialState(defaultScene());

  it('children lists what a combination holds, with the steps to it in the file, and nothing for a leaf', () => {
    expect(children(deep).map((child) => child.steps)).toEqual([
      ['any', 0],
      ['any', 1],
    ]);
    for (const kind of ['event', 'state', 'quiz', 'estimate', 'picture', 'challenge', 'code', 'info']) expect(children(goal(EXAMPLES[kind])), kind).toEqual([]);
  });

  it('goalParts reaches every goal at every depth, with its path as the file writes it', () => {
    expect(goalParts(deep, ['goal']).map(({ goal: part, path }) => `${path.join('.')}:${part.kind}`)).toEqual([
      'goal:any',
      'goal.any.0:all',
      'goal.any.0.all.0:event',
      'goal.any.0.all.1:any',
      'goal.any.0.all.1.any.0:all',
      'goal.any.0.all.1.any.0.all.0:event',
      'goal.any.0.all.1.any.0.all.1:state',
      'goal.any.1:state',
    ]);
  });

  it('tallyAction and checkGoal count an event four levels down', () => {
    const actions: LabAction[] = [
      { type: 'settings.changed', changes: { supersampling: 2 } },
      { type: 'view.zoomed' },
      { type: 'view.orbited' },
      { type: 'view.orbited' },
    ];
    let state = start;
    let tally = NO_EVENTS;
    const met = actions.map((action) => {
      state = reduce(state, action).state;
      tally = tallyAction(deep, tally, state, action);
      return checkGoal(deep, state, tally);
    });
    expect(met).toEqual([false, false, false, true]);
  });

  it('touchesGoal sees a step towards an event or a state four levels down', () => {
    const after = (action: LabAction) => reduce(start, action).state;
    const orbit: LabAction = { type: 'view.orbited' };
    const samples: LabAction = { type: 'settings.changed', changes: { supersampling: 3 } };
    const fov: LabAction = { type: 'camera.changed', changes: { fov: 50 } };
    expect(touchesGoal(deep, start, after(orbit), orbit)).toBe(true);
    expect(touchesGoal(deep, start, after(samples), samples)).toBe(true);
    expect(touchesGoal(deep, start, after(fov), fov)).toBe(false);
  });

  it('the level rules check a state path four levels down, and name where it is', () => {
    const parsed = parseLevel(
      levelFile((level) => {
        level.tasks[0].goal = {
          any: [
            {
              all: [
                {
                  any: [
                    {
                      all: [
                        { event: 'view.orbited', where: { 'rays.hideNoHits': true } },
                        { state: 'scene.settings.nope', op: '==', value: 1 },
                      ],
                    },
                  ],
                },
              ],
            },
          ],
        };
      }),
    );
    expect(parsed.ok).toBe(false);
    const errors = parsed.ok ? [] : parsed.errors.map(issueLine);
    expect(errors.some((line) => line.startsWith('tasks[0].goal.any[0].all[0].any[0].all[0].where.rays.hideNoHits: no field "hideNoHits"'))).toBe(true);
    expect(errors.some((line) => line.startsWith('tasks[0].goal.any[0].all[0].any[0].all[1].state: no field "nope"'))).toBe(true);
  });
});
