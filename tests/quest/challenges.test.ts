import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { challengeScenes, MATCH_SCORE, matchScore, meanLinearDifference, pixelDifferences } from '../../src/quest/challenge-closeness.ts';
import { checkGoal, NO_EVENTS, tallyAction, touchesGoal } from '../../src/quest/goal-check.ts';
import { goalSchema, kindOfGoal, type ChallengeGoal } from '../../src/quest/goal.ts';
import { levelSchema } from '../../src/quest/level-schema.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { loadMeshesFromDisk } from '../../src/scene/load-meshes-node.ts';
import { meshNamesInScene } from '../../src/scene/mesh-names.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { countPixelTests, type RayTests } from '../../src/tracer/triangle-test-count.ts';
import { challengeDifference } from '../support/challenge-render.ts';

/**
 * Match-the-target challenges (spec/challenges.md §2): the measure, the goal kind, the star
 * rule, and every challenge in levels/ — met by its solution's scene, not by the level's
 * starting scene, nor by the solution with any one of its settings left as it was.
 */

const challenge = (threshold = 0.01): ChallengeGoal => {
  const goal = goalSchema.parse({
    challenge: {
      target: [{ type: 'settings.changed', changes: { shadows: false } }],
      editable: ['tracer.shadows'],
      measure: { threshold },
      par: { renders: 2 },
    },
  });
  if (goal.kind !== 'challenge') throw new Error('expected a challenge goal');
  return goal;
};

describe('the challenge measure', () => {
  it('is the mean absolute difference per pixel and channel, clamped to 0..1 as the picture shows it', () => {
    const black = new Float32Array([0, 0, 0, 0, 0, 0]);
    expect(meanLinearDifference(black, black)).toBe(0);
    expect(meanLinearDifference(black, new Float32Array([1, 1, 1, 1, 1, 1]))).toBe(1);
    // One channel of one of two pixels off by 0.6 (a value above 1 counts as 1): 0.6 / 6.
    expect(meanLinearDifference(black, new Float32Array([0, 0, 0, 0, 0.6, 0]))).toBeCloseTo(0.1);
    expect(meanLinearDifference(black, new Float32Array([0, 0, 0, 0, 0, 7]))).toBeCloseTo(1 / 6);
    expect(() => meanLinearDifference(black, new Float32Array(3))).toThrow();
    expect([...pixelDifferences(black, new Float32Array([0, 0, 0, 0.3, 0.6, 0]))].map((value) => value.toFixed(2))).toEqual(['0.00', '0.30']);
  });

  it("renders the target from the level's starting scene and the learner's scene as it is, both at the measure's size", () => {
    const scene: Scene = defaultScene();
    const learner: Scene = { ...scene, settings: { ...scene.settings, supersampling: 3 } };
    const { target, attempt } = challengeScenes(scene, challenge(), learner);
    expect(target.settings).toMatchObject({ shadows: false, supersampling: scene.settings.supersampling, imageSize: [64, 48] });
    expect(attempt.settings).toMatchObject({ shadows: scene.settings.shadows, supersampling: 3, imageSize: [64, 48] });
  });
});

describe('a challenge goal', () => {
  it('is a task to do in the lab, met once a comparison comes within its threshold', () => {
    const goal = challenge(0.01);
    const state = initialState(defaultScene());
    expect(kindOfGoal(goal)).toBe('do');
    const far = tallyAction(goal, NO_EVENTS, state, { type: 'challenge.compared', difference: 0.02, renders: 1, changes: 0, rays: 0 });
    expect(checkGoal(goal, state, far)).toBe(false);
    const rendered = tallyAction(goal, far, state, { type: 'render.finished', ms: 10 });
    expect(checkGoal(goal, state, rendered)).toBe(false);
    const close = tallyAction(goal, rendered, state, { type: 'challenge.compared', difference: 0.01, renders: 2, changes: 1, rays: 0 });
    expect(checkGoal(goal, state, close)).toBe(true);
  });

  it('counts every comparison as a try, close or not', () => {
    const state = initialState(defaultScene());
    expect(touchesGoal(challenge(), state, state, { type: 'challenge.compared', difference: 0.5, renders: 1, changes: 0, rays: 0 })).toBe(true);
    expect(touchesGoal(challenge(), state, state, { type: 'render.started' })).toBe(false);
  });

  it('refuses a level file without a threshold, with controls that are not the lab’s, or with no par', () => {
    const parse = (content: unknown) => goalSchema.safeParse({ challenge: content }).success;
    const valid = { target: [{ type: 'render.saved' }], editable: ['tracer.shadows'], measure: { threshold: 0.01 }, par: { renders: 2 } };
    expect(parse(valid)).toBe(true);
    expect(parse({ ...valid, measure: {} })).toBe(false);
    expect(parse({ ...valid, editable: ['tracer.nothing'] })).toBe(false);
    expect(parse({ ...valid, par: {} })).toBe(false);
  });
});

describe('the match score', () => {
  it('is 75 at the threshold, 25 more for each tenfold step closer, 25 less for each step further, within 0..100', () => {
    expect(matchScore(0.0001, 0.0001)).toBe(MATCH_SCORE);
    expect(matchScore(0.00001, 0.0001)).toBe(100);
    expect(matchScore(0.001, 0.0001)).toBe(50);
    expect(matchScore(0.1, 0.0001)).toBe(0);
    expect(matchScore(0, 0.01)).toBe(100);
    expect(matchScore(1, 0.01)).toBe(25);
  });

  it('is a match exactly when it is 75 or more, however close to the threshold', () => {
    for (const threshold of [0.0001, 0.005, 0.03]) {
      for (const factor of [0.999, 1, 1.001, 1.5, 0.5]) {
        const difference = threshold * factor;
        expect(matchScore(difference, threshold) >= MATCH_SCORE, `${difference} against ${threshold}`).toBe(difference <= threshold);
      }
    }
  });
});

const levelsFolder = new URL('../../levels/', import.meta.url);
const challengeTasks = readdirSync(levelsFolder)
  .filter((name) => name.endsWith('.level.json'))
  .flatMap((name) => {
    const level = levelSchema.parse(JSON.parse(readFileSync(new URL(name, levelsFolder), 'utf8')));
    return level.tasks.flatMap((task) =>
      task.goal.kind === 'challenge' ? [{ name: `${level.id}/${task.id}`, scene: level.scene, goal: task.goal, solution: task.solution ?? [] }] : [],
    );
  });

/** The scene the actions leave, from the level's start; a refused action fails the test. */
function sceneAfter(scene: Scene, actions: readonly LabAction[]): Scene {
  let state = initialState(scene);
  for (const action of actions) {
    const reduced = reduce(state, action);
    expect(reduced.error, `${action.type} is refused`).toBeUndefined();
    state = reduced.state;
  }
  return state.scene;
}

/** The solution with one of its changed values left out, for each value it changes: one wrong setting each. */
function oneSettingWrong(solution: readonly LabAction[]): { name: string; actions: LabAction[] }[] {
  return solution.flatMap((action, index) =>
    'changes' in action
      ? Object.keys(action.changes).map((field) => ({
          name: `${action.type} without ${field}`,
          actions: solution.map((other, at) =>
            at === index ? ({ ...action, changes: Object.fromEntries(Object.entries(action.changes).filter(([key]) => key !== field)) } as LabAction) : other,
          ),
        }))
      : [],
  );
}

describe("the levels' challenges", () => {
  it('are there: at least two levels end in one', () => expect(challengeTasks.length).toBeGreaterThanOrEqual(2));

  it.each(challengeTasks)('$name: its target is reached by its solution, not by the start or by one setting wrong', async ({ scene, goal, solution }) => {
    const threshold = goal.challenge.measure.threshold;
    sceneAfter(scene, goal.challenge.target);
    const solved = await challengeDifference(scene, goal, sceneAfter(scene, solution));
    expect(solved, 'the solution’s difference').toBeLessThanOrEqual(threshold);
    const start = await challengeDifference(scene, goal, scene);
    expect(start, 'the starting scene’s difference').toBeGreaterThan(threshold);
    const wrongs = oneSettingWrong(solution);
    expect(wrongs.length, 'the solution changes at least two values').toBeGreaterThanOrEqual(2);
    for (const wrong of wrongs) {
      const difference = await challengeDifference(scene, goal, sceneAfter(scene, wrong.actions));
      expect(difference, wrong.name).toBeGreaterThan(threshold);
    }
  });
});

/**
 * The going-fast chapter's challenge has no target picture (a BVH never changes one:
 * docs/levels.md "A challenge without a picture"): its goals are pixels found by their rays'
 * cost. Each goal must accept exactly the pixels the real counter says the fact is true of,
 * none at the start (no pixel chosen), and the quiz's explanation must give the real count.
 */
describe('level 33: the dearest ray', () => {
  const level = levelSchema.parse(JSON.parse(readFileSync(new URL('33-the-dearest-ray.level.json', levelsFolder), 'utf8')));

  async function pixelTests(): Promise<Map<string, RayTests>> {
    const meshes = await loadMeshesFromDisk(meshNamesInScene(level.scene));
    const tracer = buildTracerScene(level.scene, meshes);
    const [columns, rows] = level.scene.camera.pixels;
    const tests = new Map<string, RayTests>();
    for (let row = 0; row < rows; row++)
      for (let column = 0; column < columns; column++) tests.set(`${column},${row}`, countPixelTests(tracer, meshes, [column, row]));
    return tests;
  }

  const goalOf = (taskId: string) => level.tasks.find((task) => task.id === taskId)!.goal;
  const accepted = (taskId: string, keys: Iterable<string>) =>
    [...keys].filter((key) =>
      checkGoal(goalOf(taskId), { ...initialState(level.scene), selectedPixel: key.split(',').map(Number) as [number, number] }, NO_EVENTS),
    );
  const where = (tests: Map<string, RayTests>, fact: (test: RayTests) => boolean) => [...tests].filter(([, test]) => fact(test)).map(([key]) => key);

  it('"in the box, not one triangle" accepts exactly the pixels whose rays meet the character’s box and test no triangle', async () => {
    const tests = await pixelTests();
    const skipped = where(tests, (test) => test.objects.some((object) => object.id === 'hero' && object.boundsHit) && test.triangles === 0);
    expect(skipped.length).toBeGreaterThan(0);
    expect(accepted('box-but-no-triangle', tests.keys())).toEqual(skipped);
    expect(checkGoal(goalOf('box-but-no-triangle'), initialState(level.scene), NO_EVENTS)).toBe(false);
  });

  it('"the dearest ray" accepts exactly the pixel whose ray tests the most triangles, a ray that misses the character', async () => {
    const tests = await pixelTests();
    const most = Math.max(...[...tests.values()].map((test) => test.triangles));
    const dearest = where(tests, (test) => test.triangles === most);
    expect(dearest).toHaveLength(1);
    expect(accepted('find-dearest', tests.keys())).toEqual(dearest);
    expect(checkGoal(goalOf('find-dearest'), initialState(level.scene), NO_EVENTS)).toBe(false);
    expect(tests.get(dearest[0])!.hitId).not.toBe('hero');
    const quiz = goalOf('predict-dearest');
    if (quiz.kind !== 'quiz') throw new Error('expected the quiz');
    expect(JSON.stringify(quiz.quiz.explanation)).toContain(`tested ${most} triangles`);
  });
});
