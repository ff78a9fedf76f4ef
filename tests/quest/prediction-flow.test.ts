import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { choiceOrder } from '../../src/quest/choice-order.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { catalogOf, FakeClock, levelFile } from '../support/quest-fixtures.ts';

/**
 * Predict → observe → explain: a prediction's verdict and explanation wait until the task
 * after it (its observer) has shown the result; a learner who expected something else is
 * first asked what they see; the next task comes when they continue.
 */

/** The test level with its tasks reordered: orbit, predict, supersample (the observer), then a do task after. */
function predictionLevel(estimate = false) {
  return levelFile((level) => {
    level.id = 'first';
    const byId = Object.fromEntries(level.tasks.map((task) => [task.id as string, task]));
    if (estimate) {
      byId.predict.goal = { estimate: { question: 'How many primary rays for 4 × 3 pixels?', answer: 12, tolerance: 0, explanation: 'One per pixel.' } };
    }
    const zoom = { ...byId.zoom, mandatory: true };
    level.tasks = [byId.orbit, byId.predict, byId.supersample, zoom];
  });
}

function setUp(level = predictionLevel(), startedAt?: string) {
  const clock = new FakeClock();
  if (startedAt) clock.wall = Date.parse(startedAt);
  const engine = new QuestEngine({ catalog: catalogOf([{ id: 'test', levels: [level] }]), progress: newProgress(clock), clock });
  const opened = engine.openLevel('first');
  if (!opened.ok) throw new Error(opened.reason);
  const store = new Store(initialState(opened.scene));
  store.subscribe(engine.observe);
  store.dispatch({ type: 'scene.loaded', scene: opened.scene });
  const view = (id: string) => engine.level?.tasks.find((task) => task.task.id === id);
  const logged = (type: LoggedEvent['type']) => engine.events.filter((event) => event.type === type);
  return { engine, store, view, logged };
}

describe('a prediction', () => {
  it('is explained only after its observer is done; a wrong one is first asked what the learner sees', () => {
    const { engine, store, view, logged } = setUp();
    store.dispatch({ type: 'view.orbited' });
    expect(view('predict')?.prediction?.stage).toBe('ask');
    engine.predict('predict', { choice: 0 });
    // Locked in: no verdict yet; the observer shows what was predicted.
    expect(view('predict')?.prediction).toMatchObject({ stage: 'wait', prediction: { choice: 0 } });
    expect(view('supersample')).toMatchObject({ status: 'current', checks: { quiz: { id: 'predict' }, prediction: { choice: 0 } } });
    expect(engine.continueAfterReveal('predict')).toBe(false);
    // Neither the task nor the score tells yet whether it was right.
    expect(view('predict')?.points).toBe(0);
    expect(engine.points).toBe(10);

    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
    // Observed: the prediction is revealed and holds the level; the next task waits.
    expect(engine.level?.revealing?.task.id).toBe('predict');
    expect(view('predict')?.prediction?.stage).toBe('reflect');
    expect(view('zoom')?.status).toBe('waiting');
    expect(engine.level?.current).toBeNull();
    expect(view('supersample')?.checks).toBeUndefined();
    store.dispatch({ type: 'view.zoomed' });
    expect(view('zoom')?.status).toBe('waiting');

    expect(engine.continueAfterReveal('predict')).toBe(false); // not before saying what they see
    expect(engine.reflect('predict', { choice: 1 })).toEqual({ correct: true });
    expect(view('predict')?.prediction).toMatchObject({ stage: 'explain', reflection: { choice: 1 } });
    expect(engine.continueAfterReveal('predict')).toBe(true);
    expect(view('predict')?.prediction?.stage).toBe('explained');
    expect(engine.level?.revealing).toBeNull();
    expect(view('zoom')?.status).toBe('current');
    expect(logged('quiz.reflected')).toMatchObject([{ task: 'predict', choice: 1, correct: true }]);
    expect(logged('quiz.explained')).toMatchObject([{ task: 'predict' }]);
  });

  it('right: explained after observing, without the question what they see', () => {
    const { engine, store, view } = setUp();
    store.dispatch({ type: 'view.orbited' });
    engine.predict('predict', { choice: 1 });
    expect(view('predict')?.prediction?.stage).toBe('wait');
    expect([view('predict')?.points, engine.points]).toEqual([0, 10]);
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
    expect(view('predict')?.prediction?.stage).toBe('explain');
    expect([view('predict')?.points, engine.points]).toEqual([10, 30]);
    expect(engine.reflect('predict', { choice: 1 })).toBeUndefined();
    expect(engine.continueAfterReveal('predict')).toBe(true);
    expect(view('zoom')?.status).toBe('current');
  });

  it('a number: right within its tolerance, revealed after observing like a choice', () => {
    const { engine, store, view, logged } = setUp(predictionLevel(true));
    store.dispatch({ type: 'view.orbited' });
    expect(engine.predict('predict', { choice: 1 })).toBeUndefined(); // a number is asked
    expect(engine.predict('predict', { value: 7 })).toEqual({ correct: false });
    expect(logged('quiz.answered')).toMatchObject([{ task: 'predict', value: 7, correct: false }]);
    expect(view('predict')?.prediction).toMatchObject({ stage: 'wait', order: [], prediction: { value: 7 } });
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
    expect(engine.reflect('predict', { value: 12 })).toEqual({ correct: true });
    expect(engine.continueAfterReveal('predict')).toBe(true);
  });

  it('"show me" on a prediction shows the answer at once: nothing to wait for', () => {
    const { engine, store, view } = setUp();
    store.dispatch({ type: 'view.orbited' });
    expect(engine.showMe('predict')).toEqual({ kind: 'answer', answer: 1 });
    expect(view('predict')).toMatchObject({ status: 'shown', prediction: { stage: 'explained' } });
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
    expect(engine.level?.revealing).toBeNull();
    expect(view('zoom')?.status).toBe('current');
  });
});

describe("the order of a quiz's choices", () => {
  it('is a permutation, the same for the same seed', () => {
    const order = choiceOrder(5, 'a/b/c');
    expect([...order].sort()).toEqual([0, 1, 2, 3, 4]);
    expect(choiceOrder(5, 'a/b/c')).toEqual(order);
  });

  it('puts the key in every place about equally often across learners', () => {
    const places = [0, 0, 0, 0];
    for (let learner = 0; learner < 4000; learner++) places[choiceOrder(4, `learner-${learner}/level/quiz`).indexOf(2)]++;
    // 1000 expected per place; binomial sd ≈ 27, so ±150 fails only a broken shuffle.
    for (const count of places) expect(Math.abs(count - 1000)).toBeLessThan(150);
  });

  it('is fixed per learner across reloads and differs between learners', () => {
    const a = setUp(predictionLevel(), '2025-03-01T09:00:00.000Z');
    const b = setUp(predictionLevel(), '2025-03-01T09:00:00.000Z');
    expect(a.view('predict')?.prediction?.order).toEqual(b.view('predict')?.prediction?.order);
    const orders = new Set<string>();
    for (let minute = 0; minute < 20; minute++) {
      const learner = setUp(predictionLevel(), `2025-03-01T09:${String(minute).padStart(2, '0')}:00.000Z`);
      orders.add(JSON.stringify(learner.view('predict')?.prediction?.order));
    }
    expect(orders.size).toBeGreaterThan(1);
  });
});
