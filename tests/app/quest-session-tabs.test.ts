import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { QuestSession } from '../../src/app/quest-session.ts';
import { Store } from '../../src/lab-state/store.ts';
import { MemoryStorage, PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import { newProgress, pointsOf, type Progress } from '../../src/quest/progress.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]);

/**
 * One storage shared by several tabs, as localStorage is: a write is seen at once by every
 * tab's reads, and each other tab hears of it later (a `storage` event), when the test
 * delivers the queued events.
 */
class SharedStorage extends MemoryStorage {
  readonly tabs: QuestSession[] = [];
  private queued: { from: QuestSession | undefined; key: string }[] = [];
  writer: QuestSession | undefined;

  override setItem(key: string, value: string): void {
    super.setItem(key, value);
    this.queued.push({ from: this.writer, key });
  }

  /** Delivers the storage events until none are left (answers to events queue more). */
  deliver(): void {
    for (let rounds = 0; this.queued.length > 0; rounds++) {
      if (rounds > 100) throw new Error('tabs keep answering each other');
      const batch = this.queued.splice(0);
      for (const { from, key } of batch) {
        for (const tab of this.tabs) if (tab !== from) this.as(tab, () => tab.storageChanged(key));
      }
    }
  }

  /** Runs `action` as `tab`, so that its writes are not echoed back to it. */
  as<T>(tab: QuestSession | undefined, action: () => T): T {
    const before = this.writer;
    this.writer = tab;
    try {
      return action();
    } finally {
      this.writer = before;
    }
  }
}

interface Tab {
  session: QuestSession;
  store: Store;
  clock: FakeClock;
}

function openTab(storage: SharedStorage): Tab {
  const store = new Store(initialState(defaultScene()));
  const clock = new FakeClock();
  const session = storage.as(undefined, () => new QuestSession({ store, catalog, storage, clock }));
  storage.tabs.push(session);
  storage.as(session, () => session.start());
  return { session, store, clock };
}

function act(storage: SharedStorage, tab: Tab, action: () => void): void {
  storage.as(tab.session, action);
}

const savedProgress = (storage: MemoryStorage): Progress => JSON.parse(storage.getItem(PROGRESS_KEY) ?? 'null');
const ids = (progress: Progress) => new Set(progress.log.events.map((event) => event.id));

describe('several tabs of the game', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('keep every task and event of every tab, even when no tab hears of the others', () => {
    const storage = new SharedStorage();
    const first = openTab(storage);
    const others = [openTab(storage), openTab(storage), openTab(storage), openTab(storage)];
    // The first tab does two tasks; the four opened with it each do one thing. No events are delivered.
    act(storage, first, () => first.store.dispatch({ type: 'view.orbited' }));
    act(storage, first, () => first.session.engine.predict('predict', { choice: 1 }));
    act(storage, others[0], () => others[0].session.engine.askHint('orbit'));
    act(storage, others[1], () => others[1].store.dispatch({ type: 'view.zoomed' }));
    act(storage, others[2], () => others[2].session.engine.skip('red-ball'));
    act(storage, others[3], () => others[3].session.engine.expandExplanation('intro'));

    const saved = savedProgress(storage);
    expect(Object.keys(saved.levels.first.tasks).sort()).toEqual(['orbit', 'predict', 'red-ball', 'zoom']);
    expect(saved.levels.first.hintsUsed).toBe(1);
    const kept = ids(saved);
    for (const tab of [first, ...others]) for (const event of tab.session.engine.events) expect(kept).toContain(event.id);
    // A sixth tab sees all of it.
    const sixth = openTab(storage);
    expect(sixth.session.engine.level?.tasks.map((task) => [task.task.id, task.status])).toEqual([
      ['orbit', 'done'],
      ['predict', 'done'],
      ['supersample', 'current'],
      ['red-ball', 'skipped'],
      ['zoom', 'done'],
    ]);
  });

  it("show each other's work: a task done in one tab moves the other tab on", () => {
    const storage = new SharedStorage();
    const [a, b] = [openTab(storage), openTab(storage)];
    const heard = vi.fn();
    b.session.subscribe(heard);
    act(storage, a, () => a.store.dispatch({ type: 'view.orbited' }));
    storage.deliver();
    expect(heard).toHaveBeenCalled();
    expect(b.session.engine.level?.current?.task.id).toBe('predict');
    expect(b.session.engine.points).toBe(10);
    // And b's own events since then reach storage with a's.
    act(storage, b, () => b.session.engine.predict('predict', { choice: 1 }));
    storage.deliver();
    // a has b's prediction, with its points (shown once its result is observed).
    expect(pointsOf(a.session.engine.progress)).toBe(20);
    expect(a.session.engine.level?.tasks.find((task) => task.task.id === 'predict')?.status).toBe('done');
    expect([...ids(savedProgress(storage))].sort()).toEqual([...ids(a.session.engine.progress)].sort());
    expect([...ids(b.session.engine.progress)].sort()).toEqual([...ids(a.session.engine.progress)].sort());
  });

  it("write back what another tab's save lost (two saves that crossed)", () => {
    const storage = new SharedStorage();
    const [a, b] = [openTab(storage), openTab(storage)];
    act(storage, a, () => a.store.dispatch({ type: 'view.orbited' }));
    // Another tab's stale write (as when two tabs write at the same moment): a's task is gone from storage.
    storage.as(undefined, () => storage.setItem(PROGRESS_KEY, JSON.stringify(b.session.engine.progress)));
    expect(savedProgress(storage).levels.first?.tasks.orbit).toBeUndefined();
    storage.deliver();
    expect(savedProgress(storage).levels.first.tasks.orbit).toEqual({ how: 'done', points: 10 });
  });

  it('follow a reset or an import made in another tab instead of bringing the old progress back', () => {
    const storage = new SharedStorage();
    const [a, b] = [openTab(storage), openTab(storage)];
    act(storage, a, () => a.store.dispatch({ type: 'view.orbited' }));
    storage.deliver();
    act(storage, b, () => b.session.reset());
    storage.deliver();
    expect(a.session.engine.points).toBe(0);
    act(storage, a, () => a.session.setLocale('nl'));
    storage.deliver();
    expect(savedProgress(storage).levels).toEqual({});
    expect(b.session.locale).toBe('nl');
  });

  it('migrate a save from before event ids without losing an event', () => {
    const storage = new SharedStorage();
    const old = newProgress(new FakeClock());
    old.log.events.push({ t: 0, type: 'session.started', at: '2025-03-01T09:00:00.000Z' }, { t: 10, type: 'tab.hidden' });
    storage.setItem(PROGRESS_KEY, JSON.stringify(old));
    const [a, b] = [openTab(storage), openTab(storage)];
    act(storage, a, () => a.store.dispatch({ type: 'view.orbited' }));
    act(storage, b, () => b.store.dispatch({ type: 'view.zoomed' }));
    storage.deliver();
    const events = savedProgress(storage).log.events;
    expect(events.filter((event) => event.id?.startsWith('saved.')).map((event) => event.type)).toEqual(['session.started', 'tab.hidden']);
    expect(events.filter((event) => event.type === 'session.started')).toHaveLength(3);
  });
});
