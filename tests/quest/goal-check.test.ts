import { describe, expect, it } from 'vitest';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { initialState, type LabState } from '../../src/lab-state/lab-state.ts';
import { checkGoal, eventMatches, fitsGoal, isRightPrediction, NO_EVENTS, tallyAction, touchesGoal, type EventTally } from '../../src/quest/goal-check.ts';
import { goalSchema, type Goal } from '../../src/quest/goal.ts';
import { problemWithPath, readPath } from '../../src/quest/state-path.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { englishReason } from '../../src/util/issue.ts';

const start = initialState(defaultScene());

/** A goal as a level file writes it, parsed. */
const goal = (json: unknown): Goal => goalSchema.parse(json);

/** Runs actions through the reducer, tallying for `g`; returns whether `g` is met after each. */
function play(g: Goal, actions: LabAction[], state: LabState = start): boolean[] {
  let tally: EventTally = NO_EVENTS;
  return actions.map((action) => {
    state = reduce(state, action).state;
    tally = tallyAction(g, tally, state, action);
    return checkGoal(g, state, tally);
  });
}

const orbit: LabAction = { type: 'view.orbited' };
const zoom: LabAction = { type: 'view.zoomed' };

describe('paths into the state', () => {
  it('read fields, positions, items by id and lengths; what is not there is undefined', () => {
    expect(readPath(start, 'scene.settings.supersampling')).toBe(1);
    expect(readPath(start, 'scene.camera.pixels[1]')).toBe(6);
    expect(readPath(start, 'scene.objects[id=red-ball].material.color')).toEqual([0.9, 0.15, 0.1]);
    expect(readPath(start, 'scene.lights[id=spot].spotAngle')).toBe(40);
    expect(readPath(start, 'scene.objects.length')).toBe(5);
    expect(readPath(start, 'scene.objects[id=nothing].position')).toBeUndefined();
    expect(readPath(start, 'selection.id')).toBeUndefined();
    expect(readPath(start, 'scene.objects[9]')).toBeUndefined();
  });

  it('are checked against a sample state, with reasons', () => {
    const problemWith = (path: string) => {
      const reason = problemWithPath(path, start);
      return reason && englishReason(reason);
    };
    expect(problemWithPath('scene.camera.fov', start)).toBeUndefined();
    expect(problemWith('scene.camera.fov.x')).toBe('scene.camera.fov is a number: it has no field "x"');
    expect(problemWith('scene.settings[0]')).toBe('scene.settings is not a list, so [0] cannot select from it');
    expect(problemWith('rays.hideNoHits')).toMatch(/^no field "hideNoHits" in rays \(it has showRays, hideNoHit, /);
    expect(problemWith('Scene')).toBe('no field "Scene" (it has scene, selection, selectedPixel, rays, gizmo, bvh, look)');
    expect(problemWith('3d')).toBe('must start with a field name, like "scene.settings.shadows", got "3d"');
  });
});

describe('event goals', () => {
  it('are met when their action happens', () => {
    expect(play(goal({ event: 'view.orbited' }), [zoom, orbit])).toEqual([false, true]);
  });

  it("look at the action's fields (with) and the state it leaves (where)", () => {
    const topLeft = goal({ event: 'pixel.selected', with: { pixel: [0, 0] } });
    expect(
      play(topLeft, [
        { type: 'pixel.selected', pixel: [1, 0] },
        { type: 'pixel.selected', pixel: [0, 0] },
      ]),
    ).toEqual([false, true]);
    const noShadows = goal({ event: 'render.finished', where: { 'scene.settings.shadows': false } });
    expect(
      play(noShadows, [
        { type: 'render.finished', ms: 5 },
        { type: 'settings.changed', changes: { shadows: false } },
        { type: 'render.finished', ms: 5 },
      ]),
    ).toEqual([false, false, true]);
  });

  it('take comparisons in where: all of them must hold at the moment of the action', () => {
    const fewSamples = goal({ event: 'render.finished', where: { 'scene.settings.supersampling': { '>=': 2, '<=': 3 } } });
    const steps = (s: number): LabAction[] => [
      { type: 'settings.changed', changes: { supersampling: s } },
      { type: 'render.finished', ms: 1 },
    ];
    expect(play(fewSamples, [...steps(4), ...steps(2)])).toEqual([false, false, false, true]);
  });

  it('look into the ray debugger’s reports: the ray a step reached (kind, depth, where from) and the term clicked', () => {
    const stepped = (type: 'primary' | 'shadow' | 'reflect', depth: number, from: string | null): LabAction => ({
      type: 'debugger.stepped',
      step: 1,
      of: 9,
      ray: { type, depth, hit: true, objectId: 'ball', lightId: null, from },
    });
    const deepReflection = goal({ event: 'debugger.stepped', with: { 'ray.type': 'reflect', 'ray.depth': { '>=': 2 } } });
    expect(play(deepReflection, [stepped('primary', 0, null), stepped('reflect', 1, 'mirror'), stepped('reflect', 2, 'mirror')])).toEqual([false, false, true]);
    const fromFloor = goal({ event: 'debugger.stepped', with: { 'ray.from': 'floor' } });
    expect(play(fromFloor, [stepped('shadow', 0, 'ball'), stepped('shadow', 0, 'floor')])).toEqual([false, true]);
    const highlight = goal({ event: 'debugger.term-clicked', with: { term: 'specular' } });
    expect(
      play(highlight, [
        { type: 'debugger.term-clicked', term: 'diffuse', lightId: 'lamp' },
        { type: 'debugger.term-clicked', term: 'specular', lightId: 'lamp' },
      ]),
    ).toEqual([false, true]);
    expect(() => goal({ event: 'debugger.term-clicked', with: { ray: 'x' } })).toThrow(/has term, lightId/);
  });

  it('count with times, and say exactly which action matched', () => {
    expect(play(goal({ event: 'view.orbited', times: 3 }), [orbit, zoom, orbit, orbit])).toEqual([false, false, false, true]);
    const selectBall = goal({ event: 'selection.changed', where: { selection: { kind: 'object', id: 'red-ball' } } });
    if (!('event' in selectBall)) throw new Error('expected an event goal');
    const ball = reduce(start, { type: 'selection.changed', selection: { kind: 'object', id: 'red-ball' } }).state;
    expect(eventMatches(selectBall, ball, { type: 'selection.changed', selection: { kind: 'object', id: 'red-ball' } })).toBe(true);
    expect(eventMatches(selectBall, start, { type: 'selection.changed', selection: null })).toBe(false);
  });
});

describe('state goals', () => {
  const at = (op: string, value: unknown, path = 'scene.settings.maxDepth') => checkGoal(goal({ state: path, op, value }), start, NO_EVENTS);

  it('compare numbers with every operator', () => {
    expect([at('==', 3), at('!=', 3), at('>', 2), at('>=', 3), at('<', 3), at('<=', 3)]).toEqual([true, false, true, true, false, true]);
    expect([at('==', 4), at('!=', 4), at('>', 3), at('>=', 4), at('<', 4), at('<=', 2)]).toEqual([false, true, false, false, true, false]);
  });

  it('compare lists and objects by content, numbers within a tiny tolerance', () => {
    expect(at('==', [0.9, 0.15, 0.1], 'scene.objects[id=red-ball].material.color')).toBe(true);
    expect(at('==', [0.9, 0.15, 0.1 + 1e-9], 'scene.objects[id=red-ball].material.color')).toBe(true);
    expect(at('==', [0.9, 0.15], 'scene.objects[id=red-ball].material.color')).toBe(false);
    expect(at('==', { mode: 'translate', space: 'world', snap: false }, 'gizmo')).toBe(true);
    expect(at('==', null, 'selection')).toBe(true);
  });

  it('use includes for list items and pieces of text', () => {
    expect(at('includes', 6, 'scene.camera.pixels')).toBe(true);
    expect(at('includes', 7, 'scene.camera.pixels')).toBe(false);
    expect(at('includes', 'spheres', 'scene.name.en')).toBe(true);
    expect(at('includes', 'bollen', 'scene.name.en')).toBe(false);
  });

  it('treat a value that is not there as equal to nothing', () => {
    expect(at('==', null, 'selection.id')).toBe(false);
    expect(at('!=', 'ball', 'selection.id')).toBe(true);
    expect(at('>', 0, 'scene.objects[id=gone].position[0]')).toBe(false);
  });

  it('hold while the state does, whatever the action', () => {
    const twoSamples = goal({ state: 'scene.settings.supersampling', op: '>=', value: 2 });
    expect(
      play(twoSamples, [{ type: 'settings.changed', changes: { supersampling: 2 } }, orbit, { type: 'settings.changed', changes: { supersampling: 1 } }]),
    ).toEqual([true, true, false]);
  });
});

describe('all and any', () => {
  it('all: every event has happened since the task was shown and every state part holds now', () => {
    const orbitAndZoom = goal({ all: [{ event: 'view.orbited' }, { event: 'view.zoomed' }] });
    expect(play(orbitAndZoom, [orbit, orbit, zoom])).toEqual([false, false, true]);
    const orbitWithShadowsOff = goal({ all: [{ event: 'view.orbited' }, { state: 'scene.settings.shadows', op: '==', value: false }] });
    expect(play(orbitWithShadowsOff, [orbit, { type: 'settings.changed', changes: { shadows: false } }])).toEqual([false, true]);
  });

  it('any: one part is enough', () => {
    const orbitOrZoom = goal({ any: [{ event: 'view.orbited' }, { state: 'scene.settings.maxDepth', op: '==', value: 5 }] });
    expect(play(orbitOrZoom, [zoom, { type: 'settings.changed', changes: { maxDepth: 5 } }])).toEqual([false, true]);
    expect(play(orbitOrZoom, [zoom, orbit])).toEqual([false, true]);
  });

  it('nest', () => {
    const nested = goal({ any: [{ all: [{ event: 'view.orbited' }, { event: 'view.zoomed' }] }, { event: 'view.flew-to-camera' }] });
    expect(play(nested, [orbit, zoom])).toEqual([false, true]);
    expect(play(nested, [{ type: 'view.flew-to-camera' }])).toEqual([true]);
  });
});

describe('quiz and info goals', () => {
  it('a quiz knows its right answer', () => {
    const quiz = goal({ quiz: { question: 'How many?', choices: ['3', '12'], answer: 1 } });
    if (!('quiz' in quiz)) throw new Error('expected a quiz goal');
    expect([isRightPrediction(quiz, { choice: 0 }), isRightPrediction(quiz, { choice: 1 })]).toEqual([false, true]);
    expect(isRightPrediction(quiz, { value: 1 })).toBe(false);
  });

  it('an estimate is right within its tolerance, on both sides, and a typed decimal on the edge counts', () => {
    const estimate = goal({ estimate: { question: 'A at 1 m?', answer: 5, tolerance: 0.5 } });
    if (!('estimate' in estimate)) throw new Error('expected an estimate goal');
    const right = (value: number) => isRightPrediction(estimate, { value });
    expect([right(4.4), right(4.5), right(5), right(5.5), right(5.6)]).toEqual([false, true, true, true, false]);
    const tenth = goal({ estimate: { question: 'Q', answer: 0.3, tolerance: 0.1 } });
    if (!('estimate' in tenth)) throw new Error('expected an estimate goal');
    expect(isRightPrediction(tenth, { value: 0.1 + 0.1 })).toBe(true);
    expect(isRightPrediction(estimate, { choice: 5 })).toBe(false);
  });

  it('a prediction must fit its form: a choice that exists, a finite number', () => {
    const quiz = goal({ quiz: { question: 'Q', choices: ['a', 'b'], answer: 0 } });
    const estimate = goal({ estimate: { question: 'Q', answer: 1, tolerance: 0 } });
    if (!('quiz' in quiz) || !('estimate' in estimate)) throw new Error('expected prediction goals');
    expect([fitsGoal(quiz, { choice: 1 }), fitsGoal(quiz, { choice: 2 }), fitsGoal(quiz, { choice: 0.5 }), fitsGoal(quiz, { value: 0 })]).toEqual([
      true,
      false,
      false,
      false,
    ]);
    expect([fitsGoal(estimate, { value: -3 }), fitsGoal(estimate, { value: Number.NaN }), fitsGoal(estimate, { choice: 0 })]).toEqual([true, false, false]);
  });

  it('quiz and info goals are never met by actions: they complete through the task panel', () => {
    expect(play(goal({ info: true }), [orbit])).toEqual([false]);
    expect(play(goal({ quiz: { question: 'Q', choices: ['a', 'b'], answer: 0 } }), [orbit])).toEqual([false]);
    expect(play(goal({ estimate: { question: 'Q', answer: 1, tolerance: 0.1 } }), [orbit])).toEqual([false]);
  });
});

describe('a step towards a goal (touchesGoal)', () => {
  const step = (g: Goal, action: LabAction) => touchesGoal(g, start, reduce(start, action).state, action);
  const [first, second] = start.scene.objects;

  it('is a change of a value a state goal looks at, compared by content: editing one object is no step towards another', () => {
    const otherColour = goal({ state: `scene.objects[id=${second.id}].material.color`, op: '!=', value: [0, 0, 0] });
    const paint: LabAction = { type: 'material.changed', id: first.id, changes: { color: [0.1, 0.5, 1] } };
    // The reducer gives every object a new (equal) value; only the painted one changed.
    expect(reduce(start, paint).state.scene.objects[1]).not.toBe(second);
    expect(step(otherColour, paint)).toBe(false);
    expect(step(goal({ state: `scene.objects[id=${first.id}].material.color`, op: '!=', value: [0, 0, 0] }), paint)).toBe(true);
  });

  it("is the goal's event with the goal's `with` fields, whatever `where` says", () => {
    const topLeftFile = { event: 'pixel.selected', with: { pixel: [0, 0] }, where: { 'scene.settings.supersampling': 4 } };
    const topLeft = goal(topLeftFile);
    expect(step(topLeft, { type: 'pixel.selected', pixel: [2, 2] })).toBe(false);
    expect(step(topLeft, { type: 'pixel.selected', pixel: [0, 0] })).toBe(true);
    expect(step(goal({ any: [topLeftFile, { event: 'view.zoomed' }] }), zoom)).toBe(true);
  });
});
