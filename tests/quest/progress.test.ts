import { describe, expect, it } from 'vitest';
import { newProgress, pointsOf, type Progress } from '../../src/quest/progress.ts';
import { exportProgress, MemoryStorage, parseProgressJson, PROGRESS_KEY, ProgressStore, type KeyValueStorage } from '../../src/quest/progress-store.ts';
import { issueLine } from '../../src/util/issue.ts';
import { progressProblemText, saveProblemText } from '../../src/i18n/progress-problem-text.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

/** Progress with something in it: a level's first task done, a render, a badge. */
function playedProgress(clock: FakeClock): Progress {
  const engine = new QuestEngine({ catalog: catalogOf([{ id: 'test', levels: [levelWithId('first')] }]), progress: newProgress(clock), clock });
  const opened = engine.openLevel('first');
  if (!opened.ok) throw new Error(opened.reason);
  const store = new Store(initialState(opened.scene));
  store.subscribe(engine.observe);
  store.dispatch({ type: 'view.orbited' });
  store.dispatch({ type: 'render.finished', ms: 40 });
  return engine.progress;
}

/** A store over `storage` and what its load() made of `saved`. */
function loadFrom(saved: string | null) {
  const storage = new MemoryStorage();
  if (saved !== null) storage.setItem(PROGRESS_KEY, saved);
  const clock = new FakeClock();
  return { storage, loaded: new ProgressStore(storage, clock).load() };
}

describe('saving and loading', () => {
  it('starts fresh, without a problem, when nothing was saved', () => {
    const { loaded } = loadFrom(null);
    expect(loaded.problem).toBeUndefined();
    expect(loaded.progress).toMatchObject({ kind: 'ray-tracer-quest-progress', version: 1, levels: {}, badges: [], sandbox: null, current: null });
    expect(loaded.progress.settings).toEqual({ locale: 'en', colorBlindPalette: false });
  });

  it('gives back what it saved: tasks, points, badges, the scene, the log', () => {
    const clock = new FakeClock();
    const progress = playedProgress(clock);
    const storage = new MemoryStorage();
    const store = new ProgressStore(storage, clock);
    expect(store.save(progress)).toEqual({ ok: true, saved: progress });
    const { progress: loaded, problem } = store.load();
    expect(problem).toBeUndefined();
    expect(loaded).toEqual(progress);
    expect(pointsOf(loaded)).toBe(10);
    expect(loaded.badges.map(({ badge }) => badge.kind)).toEqual(['first-render']);
    expect(loaded.log.events.map((event) => event.type)).toContain('render.finished');
  });

  it('fills in settings added after the progress was saved', () => {
    const saved = { ...newProgress(new FakeClock()), settings: {} };
    expect(loadFrom(JSON.stringify(saved)).loaded.progress.settings).toEqual({ locale: 'en', colorBlindPalette: false });
  });
});

describe('recovering from saved data that cannot be used', () => {
  const cases: { name: string; saved: string; kind: string; reason: RegExp }[] = [
    { name: 'garbage', saved: 'ẞ%&not json', kind: 'damaged', reason: /^\(root\): not valid JSON at line 1, column 1/ },
    { name: 'truncated JSON', saved: JSON.stringify(newProgress(new FakeClock())).slice(0, 60), kind: 'damaged', reason: /^\(root\): not valid JSON/ },
    {
      name: "another app's data",
      saved: JSON.stringify({ theme: 'dark' }),
      kind: 'foreign',
      reason: /^kind: must be "ray-tracer-quest-progress" in a progress file, got "kind" nothing$/,
    },
    {
      name: 'a newer version',
      saved: JSON.stringify({ ...newProgress(new FakeClock()), version: 2 }),
      kind: 'other-version',
      reason: /^version: this app reads progress version 1, got 2$/,
    },
  ];

  const opening: Record<string, RegExp> = {
    damaged: /^Your saved progress is damaged and could not be read\. /,
    foreign: /^The saved data is not Ray Tracer Quest progress\. /,
    'other-version': /^Your saved progress was made by another version of Ray Tracer Quest\. /,
  };
  for (const { name, saved, kind, reason } of cases) {
    it(`${name}: a fresh start, a message, and the old data kept under a backup key`, () => {
      const { storage, loaded } = loadFrom(saved);
      const { problem } = loaded;
      expect(problem?.kind).toBe(kind);
      expect(problem?.reasons[0]).toMatch(reason);
      expect(problem && progressProblemText(problem, 0)).toMatch(opening[kind]);
      expect(problem && progressProblemText(problem, 0)).toMatch(
        /You start from the beginning\. The saved data as it was is kept: download or restore it from the Menu \(Damaged saves\)\.$/,
      );
      expect(problem?.backupKey).toBe('rtq.progress.backup.2025-03-01T09:00:00.000Z');
      expect(problem?.raw).toBe(saved);
      expect(storage.getItem(problem?.backupKey ?? '')).toBe(saved);
      expect(loaded.progress.levels).toEqual({});
    });
  }

  it('never writes a backup over an older one', () => {
    const storage = new MemoryStorage();
    const clock = new FakeClock();
    const store = new ProgressStore(storage, clock);
    storage.setItem(PROGRESS_KEY, 'first damage');
    store.load();
    storage.setItem(PROGRESS_KEY, 'second damage');
    const { problem } = store.load(); // same clock reading: the backup key is taken
    expect(problem?.backupKey).toBeNull();
    expect(problem?.raw).toBe('second damage');
    expect(problem && progressProblemText(problem, 0)).toMatch(
      /no room to keep a copy of the saved data as it was, so nothing is saved over it until you download it from the Menu/,
    );
    expect(storage.getItem(`${PROGRESS_KEY}.backup.2025-03-01T09:00:00.000Z`)).toBe('first damage');
  });

  it('storage that refuses to be read: progress lasts for the page, with a message', () => {
    const blocked: KeyValueStorage = {
      getItem: () => {
        throw new Error('The operation is insecure.');
      },
      setItem: () => {},
      removeItem: () => {},
      length: 0,
      key: () => null,
    };
    const { problem, progress } = new ProgressStore(blocked, new FakeClock()).load();
    expect(problem).toMatchObject({ kind: 'unreadable-storage', reasons: ['The operation is insecure.'], backupKey: null, raw: null });
    expect(problem && progressProblemText(problem, 0)).toMatch(
      /^This browser does not let the app read its storage, so progress lasts only while this page is open\./,
    );
    expect(progress.levels).toEqual({});
  });

  const refusals = [
    {
      name: 'full storage',
      error: 'QuotaExceededError',
      kind: 'storage-full',
      text: /^The browser's storage is full, so progress is not saved\. It is kept while this page is open and saved as soon as there is room: export it \(Menu\) to be safe\.$/,
    },
    {
      name: 'storage that refuses every write',
      error: 'SecurityError',
      kind: 'storage-blocked',
      text: /^The browser does not let the app save, so progress is not saved\./,
    },
  ] as const;
  for (const { name, error, kind, text } of refusals) {
    it(`${name}: says why progress was not saved`, () => {
      const storage = new MemoryStorage();
      storage.setItem = () => {
        throw new DOMException('refused', error);
      };
      const result = new ProgressStore(storage, new FakeClock()).save(newProgress(new FakeClock()));
      expect(result).toEqual({ ok: false, kind });
      expect(saveProblemText(kind)).toMatch(text);
    });
  }
});

describe('export, import and reset', () => {
  it('exports a file that imports to the same progress', () => {
    const progress = playedProgress(new FakeClock());
    expect(parseProgressJson(exportProgress(progress))).toEqual({ ok: true, progress });
  });

  it('reads progress saved before hint offers: a hint shown by itself after idle time still loads, with its count', () => {
    const progress = playedProgress(new FakeClock());
    const old = JSON.parse(exportProgress(progress)) as Progress;
    const last = old.log.events.at(-1)!.t;
    old.log.events.push({ t: last + 45_000, id: 'saved.99', type: 'hint.shown', level: 'first', task: 'predict', step: 'text', trigger: 'idle' });
    old.levels.first.hintsUsed = 1;
    const read = parseProgressJson(JSON.stringify(old));
    expect(read).toMatchObject({ ok: true, progress: { levels: { first: { hintsUsed: 1 } } } });
    if (!read.ok) return;
    const engine = new QuestEngine({ catalog: catalogOf([{ id: 'test', levels: [levelWithId('first')] }]), progress: read.progress, clock: new FakeClock() });
    expect(engine.events.filter((event) => event.type === 'hint.shown')).toMatchObject([{ trigger: 'idle' }]);
  });

  it('refuses a file that is not progress, with reasons', () => {
    const inLines = (read: ReturnType<typeof parseProgressJson>) => (read.ok ? read : { ...read, errors: read.errors.map(issueLine) });
    expect(inLines(parseProgressJson('{"version": 1, "objects": []}'))).toEqual({
      ok: false,
      kind: 'foreign',
      errors: ['kind: must be "ray-tracer-quest-progress" in a progress file, got "kind" nothing'],
    });
    expect(inLines(parseProgressJson('[1, 2]'))).toMatchObject({
      ok: false,
      kind: 'foreign',
      errors: ['kind: must be "ray-tracer-quest-progress" in a progress file, got a list of 2 items'],
    });
  });

  it('reset starts a new epoch that replaces the saved progress, even from a tab that still has the old one', () => {
    const storage = new MemoryStorage();
    const clock = new FakeClock();
    const store = new ProgressStore(storage, clock);
    const played = playedProgress(clock);
    store.save(played);
    const fresh = store.reset(played);
    expect(fresh.levels).toEqual({});
    expect(fresh.epoch).toMatch(/^2025-03-01T09:00:00\.000Z\.[a-z0-9]{8}$/);
    store.save(fresh);
    // The other tab saves its old progress: the newer epoch wins, nothing old comes back.
    const afterOld = store.save(played);
    expect(afterOld).toMatchObject({ ok: true, saved: { levels: {}, epoch: fresh.epoch } });
    expect(store.load()).toMatchObject({ progress: { levels: {} } });
    // A second reset in the same millisecond is still later than the first.
    expect(store.reset(fresh).epoch! > fresh.epoch!).toBe(true);
  });

  it("keeps a teacher assignment's progress apart under its own key", () => {
    const storage = new MemoryStorage();
    const clock = new FakeClock();
    new ProgressStore(storage, clock, 'rtq.assignment.abc').save(playedProgress(clock));
    expect(new ProgressStore(storage, clock).load().progress.levels).toEqual({});
    expect(new ProgressStore(storage, clock, 'rtq.assignment.abc').load().progress.levels).not.toEqual({});
  });
});
