import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { challengeParSchema, challengeStars, pointsForStars, starText, type ChallengeCounts } from '../../src/quest/challenge-par.ts';
import type { LoggedEvent } from '../../src/quest/event-log.ts';
import { reconcileLevels } from '../../src/quest/progress-reconcile.ts';
import { exportProgress, readProgressJson } from '../../src/quest/progress-store.ts';
import { newProgress, type Progress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { catalogOf, FakeClock, levelFile } from '../support/quest-fixtures.ts';

/**
 * The golf score of a challenge (spec/challenges.md §2, issue 41): the par kinds a level file
 * may give, the stars a match earns by each, and the stars kept with the progress, counted in
 * the points and shown again on the level map.
 */

const counts = (renders: number, changes: number, rays: number): ChallengeCounts => ({ renders, changes, rays });

describe('a par', () => {
  it('counts renders, changes or rays, one kind per challenge', () => {
    expect(challengeParSchema.parse({ renders: 3 })).toEqual({ kind: 'renders', limit: 3 });
    expect(challengeParSchema.parse({ changes: 4 })).toEqual({ kind: 'changes', limit: 4 });
    expect(challengeParSchema.parse({ rays: 2_000_000 })).toEqual({ kind: 'rays', limit: 2_000_000 });
    for (const bad of [{}, { renders: 3, changes: 4 }, { renders: 0 }, { changes: 1.5 }, { rays: 10 }, { seconds: 3 }]) {
      expect(challengeParSchema.safeParse(bad).success, JSON.stringify(bad)).toBe(false);
    }
  });

  it('gives three stars at or under par, two within 1.5 × par rounded down, else one, by the count it names', () => {
    const renders = challengeParSchema.parse({ renders: 4 });
    expect([1, 4, 5, 6, 7, 20].map((count) => challengeStars(counts(count, 99, 9e9), renders))).toEqual([3, 3, 2, 2, 1, 1]);
    const changes = challengeParSchema.parse({ changes: 3 });
    expect([0, 3, 4, 5].map((count) => challengeStars(counts(99, count, 9e9), changes))).toEqual([3, 3, 2, 1]);
    const rays = challengeParSchema.parse({ rays: 2_000_000 });
    expect([1e6, 2e6, 3e6, 3e6 + 1].map((count) => challengeStars(counts(99, 99, count), rays))).toEqual([3, 3, 2, 1]);
    expect(starText(2)).toBe('★★☆');
  });

  it('sets the points: all of them for three stars, a third of them per star', () => {
    expect([1, 2, 3].map((stars) => pointsForStars(10, stars as 1 | 2 | 3))).toEqual([3, 7, 10]);
  });
});

/** The fixture level with its quiz replaced by a challenge (switch the shadows off): orbit, match, supersample. */
function challengeLevel(par: Record<string, number> = { renders: 2 }) {
  return levelFile((level) => {
    level.id = 'match';
    level.tasks = [
      level.tasks[0],
      {
        id: 'match',
        title: 'Match it',
        text: 'Match the target.',
        goal: {
          challenge: { target: [{ type: 'settings.changed', changes: { shadows: false } }], editable: ['tracer.shadows'], measure: { threshold: 0.01 }, par },
        },
        hints: ['Look at the shadows.'],
        solution: [
          { type: 'settings.changed', changes: { shadows: false } },
          { type: 'render.finished', ms: 10 },
        ],
      },
      ...level.tasks.slice(2),
    ];
  });
}

function play(par: Record<string, number>, comparisons: { difference: number; renders: number; changes: number; rays: number }[], progress?: Progress) {
  const clock = new FakeClock();
  const engine = new QuestEngine({ catalog: catalogOf([{ id: 'test', levels: [challengeLevel(par)] }]), progress: progress ?? newProgress(clock), clock });
  const opened = engine.openLevel('match');
  if (!opened.ok) throw new Error(opened.reason);
  const store = new Store(initialState(opened.scene));
  store.subscribe(engine.observe);
  store.dispatch({ type: 'scene.loaded', scene: opened.scene });
  store.dispatch({ type: 'view.orbited' });
  for (const comparison of comparisons) expect(store.dispatch({ type: 'challenge.compared', ...comparison })).toBeUndefined();
  store.dispatch({ type: 'settings.changed', changes: { supersampling: 2 } });
  return engine;
}

describe('a matched challenge', () => {
  it('saves its stars with the task, logs them, and earns points by them', () => {
    const engine = play({ renders: 2 }, [
      { difference: 0.2, renders: 1, changes: 1, rays: 1000 },
      { difference: 0.05, renders: 2, changes: 2, rays: 2000 },
      { difference: 0.005, renders: 3, changes: 3, rays: 3000 },
    ]);
    expect(engine.progress.levels.match.tasks.match).toEqual({ how: 'done', points: 7, stars: 2 });
    const compared = engine.events.filter((event) => event.type === 'challenge.compared');
    // Logged with the challenge task and the match score the learner read (threshold 0.01: 75 at 0.01).
    expect(compared.map((event) => [event.task, event.difference, event.renders, event.changes, event.rays, event.score])).toEqual([
      ['match', 0.2, 1, 1, 1000, 42],
      ['match', 0.05, 2, 2, 2000, 57],
      ['match', 0.005, 3, 3, 3000, 82],
    ]);
    const completed = engine.events.find(
      (event): event is Extract<LoggedEvent, { type: 'task.completed' }> => event.type === 'task.completed' && event.task === 'match',
    );
    expect(completed).toMatchObject({ task: 'match', how: 'done', points: 7, stars: 2 });
    expect(engine.points).toBe(7 + 10 + 10);
    expect(engine.level?.tasks[1]).toMatchObject({ status: 'done', stars: 2, points: 7 });
    expect(engine.level?.passed).toBe(true);
  });

  it('is scored by the count its par names', () => {
    const matchAt = { difference: 0.001, renders: 9, changes: 2, rays: 5_000_000 };
    expect(play({ changes: 2 }, [matchAt]).progress.levels.match.tasks.match.stars).toBe(3);
    expect(play({ renders: 2 }, [matchAt]).progress.levels.match.tasks.match.stars).toBe(1);
    expect(play({ rays: 4_000_000 }, [matchAt]).progress.levels.match.tasks.match.stars).toBe(2);
  });

  it('shows its stars again on the level map and when the learner comes back, after a reload', () => {
    const first = play({ renders: 2 }, [{ difference: 0.001, renders: 1, changes: 1, rays: 100 }]);
    const saved = readProgressJson(exportProgress(first.progress), new Date(0).toISOString());
    expect(saved.ok && saved.repaired).toEqual([]);
    if (!saved.ok) return;
    const again = play({ renders: 2 }, [], saved.progress);
    expect(again.map()[0].levels[0]).toMatchObject({ id: 'match', status: 'passed', stars: 3, points: 30 });
    expect(again.level?.tasks[1]).toMatchObject({ status: 'done', stars: 3 });
  });

  it('has no stars in a save from before they were kept: it still loads, with the full points', () => {
    const first = play({ renders: 2 }, [{ difference: 0.001, renders: 5, changes: 1, rays: 100 }]);
    const old = structuredClone(first.progress);
    delete old.levels.match.tasks.match.stars;
    old.log.events = old.log.events.map((event) => {
      if (event.type === 'challenge.compared') return { t: event.t, id: event.id, type: event.type, level: event.level, difference: event.difference };
      if (event.type !== 'task.completed') return event;
      const { stars: _stars, ...rest } = event;
      return rest;
    });
    const read = readProgressJson(exportProgress(old), new Date(0).toISOString());
    expect(read.ok && read.repaired).toEqual([]);
    if (!read.ok) return;
    const engine = play({ renders: 2 }, [], read.progress);
    expect(engine.map()[0].levels[0].stars).toBeUndefined();
    // Saved with 3 points for one star; without its stars the match counts as before stars existed.
    expect(first.progress.levels.match.tasks.match).toEqual({ how: 'done', points: 3, stars: 1 });
    expect(engine.progress.levels.match.tasks.match).toEqual({ how: 'done', points: 10 });
  });

  it('is not trusted for points: they are worked out again from the stars and the level file', () => {
    const engine = play({ renders: 2 }, []);
    const levels = reconcileLevels({ match: { tasks: { match: { how: 'done', points: 100, stars: 2 } }, hintsUsed: 0 } }, [engine.level!.level]);
    expect(levels.match.tasks.match).toEqual({ how: 'done', points: 7, stars: 2 });
  });
});
