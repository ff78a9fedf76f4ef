import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { shownLight } from '../../src/quest/challenge-closeness.ts';
import type { ChallengeGoal } from '../../src/quest/goal.ts';
import { levelSchema } from '../../src/quest/level-schema.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { challengeDifference } from '../support/challenge-render.ts';

/**
 * How close is close enough in the challenges whose pictures are noisy (a soft shadow's
 * random shadow rays, a path tracer's random paths): the threshold must take settings near
 * the target's and refuse the neighbouring ones, grain and all. challenges.test.ts checks
 * the start and one setting left out; this checks the steps next to the answer.
 */

describe('the measure in path mode', () => {
  it('compares the light as the render window shows it: radiance times 2^exposure', () => {
    const rgb = new Float32Array([0.1, 0.2, 0.25]);
    expect([...shownLight(rgb, { integrator: 'path', exposure: 2 })]).toEqual([0.4, 0.8, 1].map(Math.fround));
    expect(shownLight(rgb, { integrator: 'whitted', exposure: 2 })).toBe(rgb);
  });
});

function challengeOf(id: string): { scene: Scene; goal: ChallengeGoal } {
  const level = levelSchema.parse(JSON.parse(readFileSync(new URL(`../../levels/${id}.level.json`, import.meta.url), 'utf8')));
  const goal = level.tasks.map((task) => task.goal).find((candidate) => candidate.kind === 'challenge');
  if (goal?.kind !== 'challenge') throw new Error(`${id} has no challenge`);
  return { scene: level.scene, goal };
}

function sceneAfter(scene: Scene, action: LabAction): Scene {
  const reduced = reduce(initialState(scene), action);
  expect(reduced.error).toBeUndefined();
  return reduced.state.scene;
}

const lamp = (size: number, samples: number): LabAction => ({ type: 'light.changed', id: 'panel', changes: { size: [size, size], samples } });
const paths = (maxDepth: number, pathSamples: number): LabAction => ({ type: 'settings.changed', changes: { maxDepth, pathSamples } });

const cases: { level: string; near: [string, LabAction][]; off: [string, LabAction][] }[] = [
  {
    // The target: a 1.2 m lamp, 4 × 4 shadow rays.
    level: '30-match-the-soft-shadow',
    near: [
      ['a lamp 0.1 m narrower', lamp(1.1, 4)],
      ['a lamp 0.1 m wider', lamp(1.3, 4)],
    ],
    off: [
      ['a lamp 0.2 m narrower', lamp(1.0, 4)],
      ['a lamp 0.2 m wider', lamp(1.4, 4)],
      ['3 × 3 shadow rays', lamp(1.2, 3)],
      ['5 × 5 shadow rays', lamp(1.2, 5)],
    ],
  },
  {
    // The target: 2 bounces, 64 paths per pixel.
    level: '31-match-the-bounces',
    near: [
      ['48 paths', paths(2, 48)],
      ['96 paths', paths(2, 96)],
    ],
    off: [
      ['1 bounce', paths(1, 64)],
      ['3 bounces', paths(3, 64)],
      ['half the paths', paths(2, 32)],
      ['twice the paths', paths(2, 128)],
    ],
  },
];

describe("the noisy challenges' thresholds", () => {
  it.each(cases)(
    '$level: met near the target, not one step off',
    async ({ level, near, off }) => {
      const { scene, goal } = challengeOf(level);
      const threshold = goal.challenge.measure.threshold;
      for (const [name, action] of near) expect(await challengeDifference(scene, goal, sceneAfter(scene, action)), name).toBeLessThanOrEqual(threshold);
      for (const [name, action] of off) expect(await challengeDifference(scene, goal, sceneAfter(scene, action)), name).toBeGreaterThan(threshold);
    },
    60_000,
  );
});

describe("level 32's threshold", () => {
  // The target: the ball at (−0.5, 0.5, 1), a 30° field of view. The arrow keys move the ball
  // 0.1 m a press and the slider steps 1°: a drag within 2 cm matches, one key or one degree off does not.
  const shot = (position: [number, number, number], fov: number): LabAction[] => [
    { type: 'object.changed', id: 'ball', changes: { position } },
    { type: 'camera.changed', changes: { fov } },
  ];
  const near: [string, LabAction[]][] = [
    ['2 cm to the right', shot([-0.48, 0.5, 1], 30)],
    ['2 cm nearer', shot([-0.5, 0.5, 1.02], 30)],
  ];
  const off: [string, LabAction[]][] = [
    ['one key press to the right', shot([-0.4, 0.5, 1], 30)],
    ['one key press to the left', shot([-0.6, 0.5, 1], 30)],
    ['one key press nearer', shot([-0.5, 0.5, 1.1], 30)],
    ['one key press farther', shot([-0.5, 0.5, 0.9], 30)],
    ['1° narrower', shot([-0.5, 0.5, 1], 29)],
    ['1° wider', shot([-0.5, 0.5, 1], 31)],
  ];

  it('is met within a drag’s accuracy of the target, not one key press or one degree off', async () => {
    const { scene, goal } = challengeOf('32-match-the-shot');
    const threshold = goal.challenge.measure.threshold;
    const after = (actions: LabAction[]) => actions.reduce((state, action) => sceneAfter(state, action), scene);
    for (const [name, actions] of near) expect(await challengeDifference(scene, goal, after(actions)), name).toBeLessThanOrEqual(threshold);
    for (const [name, actions] of off) expect(await challengeDifference(scene, goal, after(actions)), name).toBeGreaterThan(threshold);
  }, 60_000);
});
