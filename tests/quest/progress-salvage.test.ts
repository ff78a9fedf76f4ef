import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { longestNonDecreasing } from '../../src/quest/progress-salvage.ts';
import { exportProgress, readProgressJson } from '../../src/quest/progress-store.ts';
import { newProgress, pointsOf, progressSchema, type Progress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first')] }]);
const NOW = '2025-03-02T10:00:00.000Z';

/** Progress with points, a badge and a log of at least 50 events (tab switches fill it up). */
function played(): Progress {
  const clock = new FakeClock();
  const engine = new QuestEngine({ catalog, progress: newProgress(clock), clock });
  const opened = engine.openLevel('first');
  if (!opened.ok) throw new Error(opened.reason);
  const store = new Store(initialState(opened.scene));
  store.subscribe(engine.observe);
  store.dispatch({ type: 'view.orbited' });
  store.dispatch({ type: 'render.finished', ms: 40 });
  engine.askHint('predict');
  while (engine.events.length < 50) {
    clock.advance(1000);
    engine.visibilityChanged(engine.events.at(-1)?.type !== 'tab.hidden' ? false : true);
  }
  return engine.progress;
}

const progress = played();
const points = pointsOf(progress);

/** `progress` as saved JSON, with `change` made to it. */
function damaged(change: (json: Record<string, any>) => void): string {
  const json = JSON.parse(exportProgress(progress));
  change(json);
  return JSON.stringify(json);
}

describe('damaged saved progress keeps what is not damaged', () => {
  it('one bad event out of 50: that event is left out, the points and every other event kept', () => {
    expect(progress.log.events.length).toBeGreaterThanOrEqual(50);
    expect(points).toBeGreaterThan(0);
    const read = readProgressJson(
      damaged((json) => (json.log.events[20] = { ...json.log.events[20], type: 'tab.exploded' })),
      NOW,
    );
    expect(read.ok).toBe(true);
    if (!read.ok) return;
    expect(pointsOf(read.progress)).toBe(points);
    expect(read.progress.log.events).toHaveLength(progress.log.events.length - 1);
    expect(read.progress.log.events.map((event) => event.id)).toEqual(progress.log.events.filter((_, index) => index !== 20).map((event) => event.id));
    expect(read.repaired).toHaveLength(1);
    expect(read.repaired[0]).toMatch(/^log\.events\[20\]\.type: .*\(left out\)$/);
  });

  it('an unknown language code: the default language, the points kept', () => {
    const read = readProgressJson(
      damaged((json) => (json.settings.locale = 'fr')),
      NOW,
    );
    expect(read).toMatchObject({ ok: true, progress: { settings: { locale: 'en' } } });
    if (!read.ok) return;
    expect(pointsOf(read.progress)).toBe(points);
    expect(read.repaired).toEqual(['settings.locale: must be one of en, nl, got "fr" (default)']);
  });

  it('an event with a wrong time: only that event is left out, not every event after it', () => {
    const read = readProgressJson(
      damaged((json) => (json.log.events[10].t = 9e12)),
      NOW,
    );
    expect(read.ok).toBe(true);
    if (!read.ok) return;
    expect(read.progress.log.events).toHaveLength(progress.log.events.length - 1);
    expect(read.repaired).toEqual(['log.events[10].t: must not be earlier than the event before it (left out)']);
  });

  it('a task with bad points keeps the task (the points are worked out again); one with a bad "how" is left out', () => {
    const badPoints = readProgressJson(
      damaged((json) => (json.levels.first.tasks.orbit.points = -5)),
      NOW,
    );
    expect(badPoints).toMatchObject({ ok: true, progress: { levels: { first: { tasks: { orbit: { how: 'done', points: 0 } } } } } });
    const engine = badPoints.ok ? new QuestEngine({ catalog, progress: badPoints.progress, clock: new FakeClock() }) : null;
    expect(engine?.points).toBe(points);
    const badHow = readProgressJson(
      damaged((json) => (json.levels.first.tasks.orbit.how = 'guessed')),
      NOW,
    );
    expect(badHow.ok && badHow.progress.levels.first.tasks.orbit).toBeUndefined();
    expect(badHow.ok && badHow.repaired).toEqual(['levels.first.tasks.orbit.how: must be one of done, shown, skipped, got "guessed" (task left out)']);
  });

  it('a bad hint count becomes the hints the log shows; unknown fields and a bad sandbox are left out', () => {
    const read = readProgressJson(
      damaged((json) => {
        json.levels.first.hintsUsed = 'many';
        json.surprise = 1;
        json.sandbox = { version: 99 };
      }),
      NOW,
    );
    expect(read).toMatchObject({ ok: true, progress: { levels: { first: { hintsUsed: 1 } }, sandbox: null } });
    expect(read.ok && read.progress).not.toHaveProperty('surprise');
    expect(read.ok && read.repaired).toHaveLength(3);
  });

  it('a damaged log start becomes the time of the repair', () => {
    const read = readProgressJson(
      damaged((json) => (json.log.startedAt = 'yesterday')),
      NOW,
    );
    expect(read).toMatchObject({ ok: true, progress: { log: { startedAt: NOW } } });
  });

  it('still refuses what is not progress of this version, and reads good progress without notes', () => {
    expect(readProgressJson('{"kind": "notes"}', NOW)).toMatchObject({ ok: false, kind: 'foreign' });
    expect(
      readProgressJson(
        damaged((json) => (json.version = 2)),
        NOW,
      ),
    ).toMatchObject({ ok: false, kind: 'other-version' });
    expect(readProgressJson('{ broken', NOW)).toMatchObject({ ok: false, kind: 'damaged' });
    expect(readProgressJson(exportProgress(progress), NOW)).toEqual({ ok: true, progress, repaired: [] });
  });

  it('any one damaged place: never throws, is mended unless it is the kind or version, and what it reads passes the schema', () => {
    const sample = JSON.parse(exportProgress(progress)) as unknown;
    const places = placesOf(sample);
    const junk = fc.constantFrom<unknown>(null, -1, 1e308, 'x', '', true, {}, [], [1, 'a'], { t: -3 });
    fc.assert(
      fc.property(fc.integer({ min: 1, max: places.length - 1 }), junk, fc.boolean(), (pick, value, remove) => {
        const copy = structuredClone(sample) as Record<string, unknown>;
        const path = places[pick]!;
        const parent = path.slice(0, -1).reduce<any>((node, key) => node[key], copy);
        if (remove && !Array.isArray(parent)) delete parent[path.at(-1)!];
        else parent[path.at(-1)!] = value;
        const read = readProgressJson(JSON.stringify(copy), NOW);
        // Only a damaged kind or version makes it someone else's data; anything else is mended.
        expect(read.ok).toBe(path[0] !== 'kind' && path[0] !== 'version');
        if (read.ok) expect(progressSchema.safeParse(read.progress).success).toBe(true);
      }),
      { numRuns: 300 },
    );
  });
});

describe('the longest run in time order', () => {
  it('keeps the most events whose times never go back', () => {
    expect([...longestNonDecreasing([1, 2, 900, 3, 4, 5])].sort((a, b) => a - b)).toEqual([0, 1, 3, 4, 5]);
    expect([...longestNonDecreasing([5, 1, 2, 3])].sort((a, b) => a - b)).toEqual([1, 2, 3]);
    expect(longestNonDecreasing([])).toEqual(new Set());
    expect(longestNonDecreasing([2, 2, 2]).size).toBe(3);
  });
});

/** Every place in a JSON value, as a path of keys. */
function placesOf(value: unknown, path: (string | number)[] = [], found: (string | number)[][] = []): (string | number)[][] {
  found.push(path);
  if (Array.isArray(value)) value.forEach((item, index) => placesOf(item, [...path, index], found));
  else if (value !== null && typeof value === 'object') for (const [key, item] of Object.entries(value)) placesOf(item, [...path, key], found);
  return found;
}
