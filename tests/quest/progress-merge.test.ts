import { describe, expect, it } from 'vitest';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { newProgress, type Progress } from '../../src/quest/progress.ts';
import { holdsAll, mergeLogs, mergeProgress } from '../../src/quest/progress-merge.ts';
import { FakeClock } from '../support/quest-fixtures.ts';

const START = '2025-03-01T09:00:00.000Z';

function progress(events: LoggedEvent[], change: Partial<Progress> = {}, startedAt = START): Progress {
  return { ...newProgress(new FakeClock()), log: { startedAt, events }, ...change };
}

const hidden = (t: number, id?: string): LoggedEvent => ({ t, type: 'tab.hidden', ...(id === undefined ? {} : { id }) });

describe("merging two tabs' progress", () => {
  it("keeps every event of both logs once, in time order, each tab's events in their own order", () => {
    const shared = [hidden(0, 'saved.0')];
    const a = progress([...shared, hidden(10, 'a.0'), hidden(30, 'a.1'), hidden(30, 'a.2')]);
    const b = progress([...shared, hidden(20, 'b.0'), hidden(30, 'b.1')]);
    const merged = mergeProgress(a, b).log.events.map((event) => event.id);
    expect(merged).toEqual(['saved.0', 'a.0', 'b.0', 'a.1', 'a.2', 'b.1']);
    expect(
      mergeProgress(b, a)
        .log.events.map((event) => event.id)
        .sort(),
    ).toEqual([...merged].sort());
  });

  it('keeps identical events of two tabs apart: their ids differ', () => {
    const merged = mergeProgress(progress([hidden(5, 'a.0')]), progress([hidden(5, 'b.0')]));
    expect(merged.log.events).toHaveLength(2);
  });

  it('is a union: merging again, or with itself, changes nothing', () => {
    const a = progress([hidden(0, 'a.0')], { levels: { first: { tasks: { orbit: { how: 'done', points: 10 } }, hintsUsed: 0 } } });
    const b = progress([hidden(1, 'b.0')], { levels: { first: { tasks: { zoom: { how: 'skipped', points: 0 } }, hintsUsed: 2 } } });
    const once = mergeProgress(a, b);
    expect(mergeProgress(once, b)).toEqual(once);
    expect(mergeProgress(once, a)).toEqual(once);
    expect(mergeProgress(once, once)).toEqual(once);
  });

  it("puts logs that started apart on the earlier start's clock, badges too", () => {
    const early = progress([hidden(100, 'a.0')], { badges: [{ badge: { kind: 'first-render' }, t: 100 }] });
    const late = progress([hidden(100, 'b.0')], { badges: [{ badge: { kind: 'sandbox-saved' }, t: 100 }] }, '2025-03-01T09:00:05.000Z');
    const merged = mergeProgress(late, early);
    expect(merged.log.startedAt).toBe(START);
    expect(merged.log.events.map(({ id, t }) => [id, t])).toEqual([
      ['a.0', 100],
      ['b.0', 5100],
    ]);
    expect(merged.badges).toEqual([
      { badge: { kind: 'first-render' }, t: 100 },
      { badge: { kind: 'sandbox-saved' }, t: 5100 },
    ]);
    expect(mergeLogs(late.log, early.log)).toMatchObject({ shiftOurs: 5000, shiftTheirs: 0 });
  });

  it('completes a task completed in either tab, keeping the better record, and every badge once at its earliest', () => {
    const a = progress([], {
      levels: { first: { tasks: { orbit: { how: 'shown', points: 0 }, zoom: { how: 'done', points: 5 } }, hintsUsed: 3 } },
      badges: [{ badge: { kind: 'first-render' }, t: 50 }],
    });
    const b = progress([], {
      levels: {
        first: { tasks: { orbit: { how: 'done', points: 10 } }, hintsUsed: 0 },
        second: { tasks: { predict: { how: 'done', points: 10, correct: true } }, hintsUsed: 0 },
      },
      badges: [
        { badge: { kind: 'first-render' }, t: 20 },
        { badge: { kind: 'no-hints', level: 'second' }, t: 60 },
      ],
    });
    const merged = mergeProgress(a, b);
    expect(merged.levels).toEqual({
      first: { tasks: { orbit: { how: 'done', points: 10 }, zoom: { how: 'done', points: 5 } }, hintsUsed: 3 },
      second: { tasks: { predict: { how: 'done', points: 10, correct: true } }, hintsUsed: 0 },
    });
    expect(merged.badges).toEqual([
      { badge: { kind: 'first-render' }, t: 20 },
      { badge: { kind: 'no-hints', level: 'second' }, t: 60 },
    ]);
  });

  it('counts at least the hints the merged log shows: one in each tab is two', () => {
    const hint = (id: string): LoggedEvent => ({ t: 1, id, type: 'hint.shown', level: 'first', task: 'orbit', step: 'text', trigger: 'asked' });
    const a = progress([hint('a.0')], { levels: { first: { tasks: {}, hintsUsed: 1 } } });
    const b = progress([hint('b.0')], { levels: { first: { tasks: {}, hintsUsed: 1 } } });
    expect(mergeProgress(a, b).levels.first.hintsUsed).toBe(2);
  });

  it('keeps our settings, sandbox and level to resume', () => {
    const a = progress([], { settings: { locale: 'nl', colorBlindPalette: true } });
    const b = progress([], { settings: { locale: 'en', colorBlindPalette: false } });
    expect(mergeProgress(a, b).settings).toEqual({ locale: 'nl', colorBlindPalette: true });
  });

  it('gives events saved before ids existed the same ids on both sides, so an old save merges without doubles', () => {
    const old = [hidden(0), hidden(5)];
    const merged = mergeProgress(progress([...old, hidden(9, 'a.0')]), progress([...old, hidden(7, 'b.0')]));
    expect(merged.log.events.map((event) => event.id)).toEqual(['saved.0', 'saved.1', 'b.0', 'a.0']);
  });

  it('lets a later epoch (a reset or an import) replace an earlier one instead of merging', () => {
    const old = progress([hidden(0, 'a.0')], { levels: { first: { tasks: { orbit: { how: 'done', points: 10 } }, hintsUsed: 0 } } });
    const reset = progress([hidden(0, 'b.0')], { epoch: '2025-03-01T10:00:00.000Z.abc' });
    expect(mergeProgress(old, reset)).toBe(reset);
    expect(mergeProgress(reset, old)).toBe(reset);
  });
});

describe("whether saved progress already holds a tab's", () => {
  const a = progress([hidden(0, 'a.0')], { levels: { first: { tasks: { orbit: { how: 'done', points: 10 } }, hintsUsed: 1 } } });

  it('holds its own and anything merged with it', () => {
    expect(holdsAll(a, a)).toBe(true);
    expect(holdsAll(mergeProgress(progress([hidden(3, 'b.0')]), a), a)).toBe(true);
  });

  it('does not when an event, a task, a better record, a badge or hints are missing', () => {
    expect(holdsAll(progress([]), a)).toBe(false);
    expect(holdsAll({ ...a, levels: {} }, a)).toBe(false);
    expect(holdsAll({ ...a, levels: { first: { tasks: { orbit: { how: 'shown', points: 0 } }, hintsUsed: 1 } } }, a)).toBe(false);
    expect(holdsAll({ ...a, levels: { first: { ...a.levels.first, hintsUsed: 0 } } }, a)).toBe(false);
    expect(holdsAll(a, { ...a, badges: [{ badge: { kind: 'first-render' }, t: 0 }] })).toBe(false);
  });

  it("holds an earlier epoch's progress when its own is later, never the other way round", () => {
    const reset = progress([], { epoch: '2025-03-01T10:00:00.000Z.abc' });
    expect(holdsAll(reset, a)).toBe(true);
    expect(holdsAll(a, reset)).toBe(false);
  });
});
