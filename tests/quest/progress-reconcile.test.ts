import { describe, expect, it } from 'vitest';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { reconcileLevels } from '../../src/quest/progress-reconcile.ts';
import { playableLevels } from '../../src/quest/level-index.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first')] }]);

describe('saved points are worked out again from the level files', () => {
  it("a hand-edited 1e308 becomes the task's own points; a shown task or a wrong prediction none", () => {
    const levels = reconcileLevels(
      {
        first: {
          tasks: {
            orbit: { how: 'done', points: 1e308 },
            zoom: { how: 'shown', points: 50 },
            predict: { how: 'done', points: 10, correct: false },
          },
          hintsUsed: 0,
        },
      },
      playableLevels(catalog),
    );
    expect(levels.first.tasks).toEqual({
      orbit: { how: 'done', points: 10 },
      zoom: { how: 'shown', points: 0 },
      predict: { how: 'done', points: 0, correct: false },
    });
  });

  it('keeps a task or level the game no longer has, with no more points than a task can give', () => {
    const levels = reconcileLevels(
      { gone: { tasks: { old: { how: 'done', points: 1e308 } }, hintsUsed: 2 }, first: { tasks: { renamed: { how: 'done', points: 7 } }, hintsUsed: 0 } },
      playableLevels(catalog),
    );
    expect(levels).toEqual({
      gone: { tasks: { old: { how: 'done', points: 100 } }, hintsUsed: 2 },
      first: { tasks: { renamed: { how: 'done', points: 7 } }, hintsUsed: 0 },
    });
  });

  it('the engine shows the recomputed points', () => {
    const clock = new FakeClock();
    const progress = { ...newProgress(clock), levels: { first: { tasks: { orbit: { how: 'done' as const, points: 1e308 } }, hintsUsed: 0 } } };
    expect(new QuestEngine({ catalog, progress, clock }).points).toBe(10);
  });
});
