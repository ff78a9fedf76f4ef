import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { QuestSession } from '../../src/app/quest-session.ts';
import { readSessionContext } from '../../src/app/session-context.ts';
import type { ShowMeStage } from '../../src/app/show-me-player.ts';
import { Store } from '../../src/lab-state/store.ts';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { assignmentProgressKey } from '../../src/classroom/assignment-id.ts';
import { MemoryStorage, PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]);

function session(storage = new MemoryStorage(), assignment: Assignment | null = null) {
  const store = new Store(initialState(defaultScene()));
  return { store, storage, session: new QuestSession({ store, catalog, storage, assignment, clock: new FakeClock() }) };
}

const saved = (storage: MemoryStorage, key = PROGRESS_KEY) => JSON.parse(storage.getItem(key) ?? 'null');

describe('the quest session', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('starts a newcomer in the first level, with its scene loaded into the store', () => {
    const { store, session: game } = session();
    expect(game.start()).toEqual({ kind: 'level', id: 'first' });
    expect(store.state.scene.camera.pixels).toEqual([4, 3]);
    expect(game.engine.level?.current?.task.id).toBe('orbit');
  });

  it('keeps the ray palette with the progress: chosen once, in the lab at the next visit and after an import', () => {
    const { store, storage, session: game } = session();
    game.start();
    expect(saved(storage).settings.colorBlindPalette).toBe(false);
    store.dispatch({ type: 'rays.changed', changes: { colorBlindPalette: true } });
    expect(saved(storage).settings.colorBlindPalette).toBe(true);
    game.dispose();

    const next = session(storage);
    expect(next.store.state.rays.colorBlindPalette).toBe(true);
    // A level's scene keeps it (the reducer keeps the palette across scene.loaded).
    next.session.start();
    expect(next.store.state.rays.colorBlindPalette).toBe(true);
    // A progress file without it (the default palette) brings the default back.
    const file = JSON.parse(next.session.exportText());
    file.settings.colorBlindPalette = false;
    expect(next.session.importText(JSON.stringify(file))).toEqual({ ok: true, repaired: [] });
    expect(next.store.state.rays.colorBlindPalette).toBe(false);
  });

  it('saves every change and resumes the level after a reload', () => {
    const { store, storage, session: game } = session();
    game.start();
    store.dispatch({ type: 'view.orbited' });
    expect(saved(storage).levels.first.tasks.orbit.how).toBe('done');

    const again = session(storage).session;
    expect(again.start()).toEqual({ kind: 'level', id: 'first' });
    expect(again.engine.level?.tasks.find((task) => task.task.id === 'orbit')?.status).toBe('done');
  });

  it('opens the map for a learner who left the levels, and keeps level 2 locked until level 1 is passed', () => {
    const { session: game } = session();
    game.start();
    game.openMap();
    expect(game.mode).toEqual({ kind: 'map' });
    expect(game.openLevel('second')).toEqual({ ok: false, reason: 'locked' });
    expect(game.nextLevel()).toBeUndefined();
  });

  it('plays "show me" on the stage, one step after another', () => {
    const { session: game } = session();
    game.start();
    const orbit = vi.fn();
    const stage = { orbit } as unknown as ShowMeStage;
    game.engine.askHint('orbit');
    game.engine.askHint('orbit');
    game.engine.askHint('orbit');
    game.showMe('orbit', stage);
    vi.advanceTimersByTime(600);
    expect(orbit).toHaveBeenCalledOnce();
  });

  it('recovers from damaged progress with a message and a backup', () => {
    const storage = new MemoryStorage();
    storage.setItem(PROGRESS_KEY, '{ not json');
    const { session: game } = session(storage);
    expect(game.problem?.kind).toBe('damaged');
    expect(game.problem?.backupKey).toMatch(/^rtq\.progress\.backup\./);
    expect(game.start()).toEqual({ kind: 'level', id: 'first' });
  });

  it('reports full storage from the start of every visit while it lasts, not only after a change', () => {
    const storage = new MemoryStorage();
    session(storage).session.dispose(); // a first visit saved progress
    const setItem = storage.setItem.bind(storage);
    storage.setItem = () => {
      throw new DOMException('quota', 'QuotaExceededError');
    };
    expect(session(storage).session.saveProblem).toBe('storage-full');
    expect(session(storage).session.saveProblem).toBe('storage-full');
    storage.setItem = setItem;
    expect(session(storage).session.saveProblem).toBeNull();
  });

  it('imports a valid progress file, refuses another, and resets', () => {
    const { store, session: game } = session();
    game.start();
    store.dispatch({ type: 'view.orbited' });
    const file = game.exportText();
    game.reset();
    expect(game.engine.points).toBe(0);
    expect(game.importText('{"kind": "something else"}')).toMatchObject({ ok: false });
    expect(game.engine.points).toBe(0);
    expect(game.importText(file)).toEqual({ ok: true, repaired: [] });
    expect(game.engine.points).toBe(10);
  });

  it('keeps the free lab scene as the sandbox: a settled edit at once, a dragged value once it rests', () => {
    const { store, storage, session: game } = session();
    game.openFreeLab();
    store.dispatch({ type: 'view.orbited' });
    expect(game.engine.progress.sandbox).toBeNull(); // orbiting is no edit
    store.dispatch({ type: 'object.added', shape: 'sphere' });
    expect(game.engine.progress.sandbox).toBe(store.state.scene);
    expect(saved(storage).sandbox.objects).toHaveLength(store.state.scene.objects.length);
    const id = store.state.scene.objects.at(-1)!.id;
    vi.advanceTimersByTime(1000);
    store.dispatch({ type: 'object.changed', id, changes: { position: [1, 2, 3] } }, { live: true });
    expect(saved(storage).sandbox.objects.at(-1).position).not.toEqual([1, 2, 3]);
    vi.advanceTimersByTime(1000);
    expect(saved(storage).sandbox.objects.at(-1).position).toEqual([1, 2, 3]);
  });

  it('saves a waiting sandbox edit when the page is left, before it rests', () => {
    const { store, storage, session: game } = session();
    game.openFreeLab();
    store.dispatch({ type: 'object.added', shape: 'sphere' });
    const id = store.state.scene.objects.at(-1)!.id;
    store.dispatch({ type: 'object.changed', id, changes: { position: [4, 5, 6] } }, { live: true });
    game.flush();
    expect(saved(storage).sandbox.objects.at(-1).position).toEqual([4, 5, 6]);
  });

  it('changes the level texts language', () => {
    const { session: game } = session();
    game.setLocale('nl');
    expect(game.locale).toBe('nl');
  });
});

describe('an assignment', () => {
  const assignment: Assignment = {
    version: 1,
    title: 'Lesson 2',
    levels: ['second', 'first'],
    requiredTasks: { second: ['orbit'] },
    otherLevels: 'hidden',
    locale: 'nl',
    askParticipantCode: true,
    survey: null,
  };

  it('plays its levels in its order, with its required tasks, locale and own progress key', () => {
    const { store, storage, session: game } = session(new MemoryStorage(), assignment);
    expect(game.catalog.chapters.map((chapter) => chapter.entries.map((entry) => entry.id))).toEqual([['second', 'first']]);
    expect(game.locale).toBe('nl');
    game.setParticipantCode('A17');
    expect(game.start()).toEqual({ kind: 'level', id: 'second' });
    store.dispatch({ type: 'view.orbited' });
    expect(game.engine.level?.passed).toBe(true);
    expect(game.nextLevel()).toBe('first');
    expect(saved(storage, assignmentProgressKey(assignment)).levels.second.tasks.orbit.how).toBe('done');
    expect(storage.getItem(PROGRESS_KEY)).toBeNull();
  });

  it('asks for a participant code once and keeps it next to the progress', () => {
    const { storage, session: game } = session(new MemoryStorage(), assignment);
    expect(game.needsParticipantCode).toBe(true);
    game.setParticipantCode('A17');
    expect(game.needsParticipantCode).toBe(false);
    expect(readSessionContext(storage, game.progressKey)).toMatchObject({ participantCode: 'A17' });
    expect(session(storage, assignment).session.needsParticipantCode).toBe(false);
  });

  it('starts nothing while the code is asked: the level and its first task start when the code is given', () => {
    const store = new Store(initialState(defaultScene()));
    const clock = new FakeClock();
    const game = new QuestSession({ store, catalog, storage: new MemoryStorage(), assignment, clock });
    expect(game.start()).toEqual({ kind: 'map' });
    expect(game.engine.events.some((event) => event.type === 'level.opened' || event.type === 'task.shown')).toBe(false);
    clock.advance(10_000);
    game.setParticipantCode('A17');
    expect(game.mode).toEqual({ kind: 'level', id: 'second' });
    const shown = game.engine.events.find((event) => event.type === 'task.shown');
    expect(shown?.t).toBeGreaterThanOrEqual(10_000);
  });

  it('keeps one attempt id across reloads and makes a new one when the learner starts again', () => {
    const { storage, session: game } = session(new MemoryStorage(), assignment);
    const first = game.context.attemptId;
    expect(first).toMatch(/^[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}$/);
    game.setParticipantCode('A17');
    expect(session(storage, assignment).session.context).toEqual({ participantCode: 'A17', attemptId: first });
    game.reset();
    expect(game.context.attemptId).not.toBe(first);
    expect(game.context.participantCode).toBe('A17');
    expect(readSessionContext(storage, game.progressKey).attemptId).toBe(game.context.attemptId);
  });

  it('reopens a finished assignment on its closing screen, not on its last level', () => {
    const oneLevel: Assignment = { ...assignment, levels: ['second'], askParticipantCode: false };
    const { store, storage, session: game } = session(new MemoryStorage(), oneLevel);
    expect(game.start()).toEqual({ kind: 'level', id: 'second' });
    store.dispatch({ type: 'view.orbited' });
    expect(game.allPassed).toBe(true);
    const again = session(storage, oneLevel).session;
    expect(again.start()).toEqual({ kind: 'finished' });
    expect(again.engine.events.filter((event) => event.type === 'level.opened')).toHaveLength(1);
  });

  it('lists a level it names that the game does not have as broken', () => {
    const { session: game } = session(new MemoryStorage(), { ...assignment, levels: ['first', 'nowhere'] });
    const entry = game.catalog.chapters[0]?.entries[1];
    expect(entry?.ok).toBe(false);
  });
});
