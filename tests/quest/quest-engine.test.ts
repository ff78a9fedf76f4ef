import { issueLine } from '../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import type { RequiredTasks } from '../../src/quest/level-gate.ts';
import { newProgress, type Progress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { catalogOf, FakeClock, levelFile, levelWithId } from '../support/quest-fixtures.ts';

/**
 * The engine as the app uses it: a store whose actions it observes, a level opened and its
 * scene loaded, then the learner's actions through the store and calls from the task panel.
 */
function setUp(options: { levels?: Record<string, unknown>[]; progress?: Progress; requiredTasks?: RequiredTasks; clock?: FakeClock } = {}) {
  const clock = options.clock ?? new FakeClock();
  const catalog = catalogOf([{ id: 'test', levels: options.levels ?? [levelWithId('first'), levelWithId('second')] }]);
  const engine = new QuestEngine({
    catalog,
    progress: options.progress ?? newProgress(clock),
    clock,
    requiredTasks: options.requiredTasks,
    idleHintMs: 30_000,
  });
  let store: Store | undefined;
  const open = (id: string) => {
    const opened = engine.openLevel(id);
    if (!opened.ok) throw new Error(`could not open ${id}: ${opened.reason}`);
    store = new Store(initialState(opened.scene));
    store.subscribe(engine.observe);
    store.dispatch({ type: 'scene.loaded', scene: opened.scene });
    return store;
  };
  const status = () => Object.fromEntries(engine.level?.tasks.map((view) => [view.task.id, view.status]) ?? []);
  const logged = <Type extends LoggedEvent['type']>(type: Type) =>
    engine.events.filter((event): event is Extract<LoggedEvent, { type: Type }> => event.type === type);
  return { clock, engine, open, status, logged };
}

/** Plays the test level's three mandatory tasks. */
function passFirstLevel(setup: ReturnType<typeof setUp>) {
  const store = setup.open('first');
  store.dispatch({ type: 'view.orbited' });
  setup.engine.predict('predict', { choice: 1 });
  store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
  return store;
}

describe('playing a level', () => {
  it('does the mandatory tasks in order and awards their points', () => {
    const setup = setUp();
    const store = setup.open('first');
    expect(setup.status()).toEqual({ orbit: 'current', predict: 'waiting', supersample: 'waiting', 'red-ball': 'open', zoom: 'open' });
    store.dispatch({ type: 'view.orbited' });
    expect(setup.status()).toMatchObject({ orbit: 'done', predict: 'current' });
    expect(setup.engine.predict('predict', { choice: 1 })).toEqual({ correct: true });
    expect(setup.engine.level?.current?.task.id).toBe('supersample');
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
    expect(setup.engine.level).toMatchObject({ passed: true, current: null, points: 30, maxPoints: 40 });
    expect(setup.engine.points).toBe(30);
  });

  it("does not count a later task's event before its turn, but accepts a state already reached", () => {
    const setup = setUp();
    const store = setup.open('first');
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 3 } });
    expect(setup.status().supersample).toBe('waiting');
    store.dispatch({ type: 'view.orbited' });
    setup.engine.predict('predict', { choice: 1 });
    // Supersampling was already 3 when the task came up: it is done at once.
    expect(setup.status().supersample).toBe('done');
  });

  it('completes optional tasks whenever their goal holds, for their own points', () => {
    const setup = setUp();
    const store = setup.open('first');
    store.dispatch({ type: 'material.changed', id: 'ball', changes: { color: [1, 0, 0] } });
    expect(setup.status()).toMatchObject({ orbit: 'current', 'red-ball': 'done' });
    expect(setup.engine.points).toBe(5);
  });

  it('ignores refused actions', () => {
    const setup = setUp();
    const store = setup.open('first');
    store.dispatch({ type: 'view.orbited' });
    setup.engine.predict('predict', { choice: 1 });
    expect(store.dispatch({ type: 'settings.changed', changes: { supersampling: 40 } })).toMatchObject([{ path: 'settings.supersampling' }]);
    expect(setup.status().supersample).toBe('current');
  });

  it('completes a task with the value the learner settles on, not one a drag passes', () => {
    const setup = setUp();
    const store = setup.open('first');
    store.dispatch({ type: 'view.orbited' });
    setup.engine.predict('predict', { choice: 1 });
    // Dragging the slider through 2 on its way to 1 starts nothing and completes nothing.
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } }, { live: true });
    expect(setup.status().supersample).toBe('current');
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 1 } });
    expect(setup.status().supersample).toBe('current');
    // Let go at 2: done.
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } }, { live: true });
    store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
    expect(setup.status().supersample).toBe('done');
  });

  it('completes an info step with Next, and only the current one', () => {
    const withInfo = levelFile((level) => {
      level.id = 'first';
      level.tasks.splice(1, 0, { id: 'read', title: 'Read', text: 'About rays.', goal: { info: true } });
    });
    const setup = setUp({ levels: [withInfo] });
    const store = setup.open('first');
    expect(setup.engine.next()).toBe(false);
    store.dispatch({ type: 'view.orbited' });
    expect(setup.engine.next()).toBe(true);
    expect(setup.status()).toMatchObject({ read: 'done', predict: 'current' });
  });

  it('records a wrong prediction: the quiz is done, without points', () => {
    const setup = setUp();
    const store = setup.open('first');
    expect(setup.engine.predict('predict', { choice: 1 })).toBeUndefined(); // not its turn yet
    store.dispatch({ type: 'view.orbited' });
    expect(setup.engine.predict('predict', { choice: 0 })).toEqual({ correct: false });
    expect(setup.engine.level?.tasks[1]).toMatchObject({ status: 'done', points: 0, correct: false });
    expect(setup.logged('quiz.answered')).toMatchObject([{ level: 'first', task: 'predict', choice: 0, correct: false }]);
    expect(setup.engine.predict('predict', { choice: 1 })).toBeUndefined(); // answered once
  });

  it("logs an optional task as started at the learner's first move towards it, not when the level opens", () => {
    const setup = setUp();
    const store = setup.open('first');
    expect(setup.logged('task.shown').map((event) => [event.task, event.kind])).toEqual([
      ['red-ball', 'do'],
      ['zoom', 'do'],
      ['orbit', 'do'],
    ]);
    setup.clock.advance(5_000);
    // Orbiting is the current task's; it moves neither optional task along.
    store.dispatch({ type: 'view.orbited' });
    expect(setup.logged('task.started')).toEqual([]);
    setup.clock.advance(5_000);
    store.dispatch({ type: 'material.changed', id: 'ball', changes: { color: [0, 0, 1] } });
    setup.engine.askHint('red-ball');
    setup.engine.askHint('red-ball');
    expect(setup.logged('task.started')).toEqual([{ t: 10_000, id: expect.any(String), type: 'task.started', level: 'first', task: 'red-ball' }]);
    setup.engine.skip('zoom');
    expect(setup.logged('task.started').map((event) => event.task)).toEqual(['red-ball', 'zoom']);
    expect(setup.logged('task.shown').find((event) => event.task === 'predict')?.kind).toBe('quiz');
  });

  it('skips optional tasks only', () => {
    const setup = setUp();
    setup.open('first');
    expect(setup.engine.skip('orbit')).toBe(false);
    expect(setup.engine.skip('zoom')).toBe(true);
    expect(setup.logged('task.completed')).toMatchObject([{ task: 'zoom', how: 'skipped', points: 0, mandatory: false, required: false }]);
  });

  it('logs explanations opened, for the intro and for tasks', () => {
    const setup = setUp();
    setup.open('first');
    setup.engine.expandExplanation('intro');
    setup.engine.expandExplanation('orbit');
    expect(setup.logged('explanation.expanded')).toMatchObject([
      { level: 'first', task: null },
      { level: 'first', task: 'orbit' },
    ]);
  });
});

describe('the gate', () => {
  it('opens the next level when every mandatory task of this one is done', () => {
    const setup = setUp();
    expect(setup.engine.levelStatus('second')).toBe('locked');
    expect(setup.engine.openLevel('second')).toEqual({ ok: false, reason: 'locked' });
    passFirstLevel(setup);
    expect(setup.logged('level.passed')).toMatchObject([{ level: 'first' }]);
    expect(setup.engine.levelStatus('first')).toBe('passed');
    expect(setup.engine.levelStatus('second')).toBe('open');
  });

  it("follows a teacher's required tasks instead of the mandatory ones", () => {
    const setup = setUp({ requiredTasks: { first: ['orbit', 'red-ball'] } });
    const store = setup.open('first');
    expect(setup.status()).toMatchObject({ orbit: 'current', predict: 'open', supersample: 'open', 'red-ball': 'waiting' });
    store.dispatch({ type: 'view.orbited' });
    store.dispatch({ type: 'material.changed', id: 'ball', changes: { color: [1, 0, 0] } });
    expect(setup.engine.levelStatus('second')).toBe('open');
  });

  it('shows broken levels with their reasons on the map, and lets the next one open past them', () => {
    const broken = levelFile((level) => {
      level.id = 'broken';
      level.tasks = [];
    });
    const setup = setUp({ levels: [levelWithId('first'), broken, levelWithId('third')] });
    passFirstLevel(setup);
    const [map] = setup.engine.map();
    expect(map.levels.map(({ id, status, errors, points }) => ({ id, status, errors: errors.map(issueLine), points }))).toEqual([
      { id: 'first', status: 'passed', errors: [], points: 30 },
      { id: 'broken', status: 'broken', errors: ['tasks: must have at least 3 items, got a list of 0 items'], points: 0 },
      { id: 'third', status: 'open', errors: [], points: 0 },
    ]);
    expect(setup.engine.openLevel('broken')).toEqual({ ok: false, reason: 'broken' });
  });
});

describe('the hint ladder', () => {
  it('climbs text hints, then guidance, then offers "show me"; every rung is logged', () => {
    const setup = setUp();
    setup.open('first');
    const { engine } = setup;
    expect(engine.level?.current?.nextHint).toBe('text');
    expect(engine.askHint('orbit')).toBe('text');
    expect(engine.askHint('orbit')).toBe('text');
    expect(engine.level?.current?.hints).toEqual(['Drag in the view.', 'Or use the arrow buttons.']);
    expect(engine.level?.ring).toBeNull();
    expect(engine.askHint('orbit')).toBe('guidance');
    expect(engine.level?.ring).toBe('view.orbit-buttons');
    expect(engine.level?.current?.nextHint).toBe('show-me');
    expect(engine.askHint('orbit')).toBeUndefined();
    expect(setup.logged('hint.shown').map(({ step, trigger }) => `${step}/${trigger}`)).toEqual(['text/asked', 'text/asked', 'guidance/asked']);
    expect(engine.askHint('supersample')).toBeUndefined(); // not its turn
  });

  it('"show me" returns the solution; when it completes the task, the task is shown, not earned', () => {
    const setup = setUp();
    const store = setup.open('first');
    const shown = setup.engine.showMe('orbit');
    expect(shown).toEqual({ kind: 'actions', actions: [{ type: 'view.orbited' }] });
    if (shown?.kind !== 'actions') throw new Error('expected actions');
    for (const action of shown.actions) store.dispatch(action);
    expect(setup.engine.level?.tasks[0]).toMatchObject({ status: 'shown', points: 0 });
    expect(setup.engine.level?.ring).toBeNull();
    expect(setup.logged('hint.shown')).toMatchObject([{ task: 'orbit', step: 'show-me' }]);
    expect(setup.logged('task.completed')).toMatchObject([{ task: 'orbit', how: 'shown', points: 0 }]);
  });

  it('"show me" on a quiz reveals the answer and completes it as shown', () => {
    const setup = setUp();
    const store = setup.open('first');
    store.dispatch({ type: 'view.orbited' });
    expect(setup.engine.showMe('predict')).toEqual({ kind: 'answer', answer: 1 });
    expect(setup.status().predict).toBe('shown');
  });

  it('offers the first rung after idle time, once, and not while the tab is hidden; an offer is not a hint used', () => {
    const setup = setUp();
    setup.open('first');
    const { clock, engine } = setup;
    clock.advance(29_000);
    engine.tick();
    expect(setup.logged('hint.offered')).toEqual([]);
    engine.visibilityChanged(false);
    clock.advance(60_000);
    engine.tick();
    expect(setup.logged('hint.offered')).toEqual([]);
    engine.visibilityChanged(true);
    clock.advance(30_000);
    engine.tick();
    expect(setup.logged('hint.offered')).toMatchObject([{ level: 'first', task: 'orbit', step: 'text' }]);
    // Offered, not shown: no hint text, nothing used, the ladder where it was.
    expect(engine.level?.current).toMatchObject({ hintOffered: true, hints: [], nextHint: 'text' });
    expect(setup.logged('hint.shown')).toEqual([]);
    expect(engine.progress.levels.first?.hintsUsed ?? 0).toBe(0);
    clock.advance(60_000);
    engine.tick();
    expect(setup.logged('hint.offered')).toHaveLength(1);
    expect(setup.logged('tab.hidden')).toHaveLength(1);
    expect(setup.logged('tab.visible')).toHaveLength(1);
  });

  it('opening an offered hint shows it and counts it as used, logged as offered', () => {
    const setup = setUp();
    setup.open('first');
    const { clock, engine } = setup;
    clock.advance(30_000);
    engine.tick();
    expect(engine.askHint('orbit')).toBe('text');
    expect(engine.level?.current).toMatchObject({ hintOffered: false, hints: ['Drag in the view.'] });
    expect(engine.progress.levels.first.hintsUsed).toBe(1);
    // The next rung is the learner's own request.
    expect(engine.askHint('orbit')).toBe('text');
    expect(setup.logged('hint.shown').map(({ step, trigger }) => `${step}/${trigger}`)).toEqual(['text/offered', 'text/asked']);
    // A task that already had a hint gets no offer.
    clock.advance(60_000);
    engine.tick();
    expect(setup.logged('hint.offered')).toHaveLength(1);
  });

  it('offers nothing on an info step, nor on a task with only "show me" on its ladder', () => {
    const quiet = levelFile((level) => {
      level.id = 'first';
      level.tasks.splice(1, 0, { id: 'read', title: 'Read', text: 'About rays.', goal: { info: true }, guide: 'tracer.supersampling' });
      level.tasks[2].hints = [];
    });
    const setup = setUp({ levels: [quiet] });
    const store = setup.open('first');
    store.dispatch({ type: 'view.orbited' });
    setup.clock.advance(60_000);
    setup.engine.tick();
    expect(setup.engine.level?.current?.task.id).toBe('read');
    setup.engine.next();
    setup.clock.advance(60_000);
    setup.engine.tick();
    expect(setup.engine.level?.current).toMatchObject({ task: { id: 'predict' }, nextHint: 'show-me', hintOffered: false });
    expect(setup.logged('hint.offered')).toEqual([]);
  });

  it('counts any action as activity', () => {
    const setup = setUp();
    const store = setup.open('first');
    setup.clock.advance(20_000);
    store.dispatch({ type: 'view.zoomed' });
    setup.clock.advance(20_000);
    setup.engine.tick();
    expect(setup.logged('hint.shown')).toEqual([]);
  });
});

describe('badges', () => {
  it("first render, no hints in a level, a finished chapter, every task, a saved sandbox, a level's own badge", () => {
    const withBadge = levelFile((level) => {
      level.id = 'first';
      level.badges = [{ id: 'painter', title: 'Painter', text: 'You painted the ball.', tasks: ['red-ball'] }];
    });
    const setup = setUp({ levels: [withBadge] });
    const store = passFirstLevel(setup);
    store.dispatch({ type: 'render.finished', ms: 12 });
    store.dispatch({ type: 'render.finished', ms: 10 });
    store.dispatch({ type: 'material.changed', id: 'ball', changes: { color: [1, 0, 0] } });
    store.dispatch({ type: 'view.zoomed' });
    setup.engine.saveSandbox(store.state.scene);
    expect(setup.engine.badges.map(({ badge }) => badge)).toEqual([
      { kind: 'chapter-done', chapter: 'test' },
      { kind: 'no-hints', level: 'first' },
      { kind: 'first-render' },
      { kind: 'level-badge', level: 'first', badge: 'painter' },
      { kind: 'every-task', level: 'first' },
      { kind: 'sandbox-saved' },
    ]);
    expect(setup.logged('badge.earned')).toHaveLength(6);
  });

  it('no no-hints badge when a hint was used', () => {
    const setup = setUp();
    setup.open('first');
    setup.engine.askHint('orbit');
    passFirstLevel(setup);
    expect(setup.engine.badges.some(({ badge }) => badge.kind === 'no-hints')).toBe(false);
  });

  it('keeps the no-hints badge for a hint offered but not opened, not for one opened', () => {
    const badgeAfterIdle = (open: boolean) => {
      const setup = setUp();
      setup.open('first');
      setup.clock.advance(30_000);
      setup.engine.tick();
      if (open) setup.engine.askHint('orbit');
      passFirstLevel(setup);
      return setup.engine.badges.some(({ badge }) => badge.kind === 'no-hints');
    };
    expect(badgeAfterIdle(false)).toBe(true);
    expect(badgeAfterIdle(true)).toBe(false);
  });
});

describe('resuming', () => {
  it('keeps tasks, points and the scene across a reload, and continues the log', () => {
    const first = setUp();
    const store = first.open('first');
    store.dispatch({ type: 'view.orbited' });
    store.dispatch({ type: 'material.changed', id: 'ball', changes: { color: [0, 0, 1] } });
    const saved = JSON.parse(JSON.stringify(first.engine.progress)) as Progress;

    // The reload: a new page, so a new monotonic clock that starts near 0, ten seconds later.
    const clock = new FakeClock();
    clock.monotonic = 50;
    clock.wall = first.clock.wall + 10_000;
    const second = setUp({ progress: saved, clock });
    expect(second.engine.progress.current?.level).toBe('first');
    const resumed = second.open('first');
    expect(resumed.state.scene.objects[0].material.color).toEqual([0, 0, 1]);
    expect(second.engine.level?.sceneKept).toBe(true);
    expect(second.status()).toMatchObject({ orbit: 'done', predict: 'current' });
    const times = second.engine.events.map((event) => event.t);
    expect(times).toEqual([...times].sort((a, b) => a - b));
    expect(second.logged('session.started')).toHaveLength(2);
    expect(second.logged('session.started')[1].t).toBeGreaterThanOrEqual(saved.log.events.at(-1)!.t + 10_000);
  });

  it('opens another level with its own scene, and says so', () => {
    const setup = setUp();
    passFirstLevel(setup);
    expect(setup.engine.level?.sceneKept).toBe(false);
    setup.open('second');
    expect(setup.engine.level?.sceneKept).toBe(false);
    setup.open('first');
    expect(setup.engine.level?.sceneKept).toBe(false);
  });

  it('tells listeners what changed, with the events logged', () => {
    const setup = setUp();
    const heard: string[][] = [];
    setup.engine.subscribe((events) => heard.push(events.map((event) => event.type)));
    const store = setup.open('first');
    store.dispatch({ type: 'view.orbited' });
    expect(heard).toEqual([
      ['level.opened', 'task.shown', 'task.shown', 'task.shown'],
      [], // scene.loaded: only the remembered scene changed
      ['task.completed', 'task.shown'],
    ]);
  });
});
