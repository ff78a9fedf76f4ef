import { issueLine } from '../../src/util/issue.ts';
import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { TaskViews } from '../../src/app/task-views.ts';
import { checkGoal, NO_EVENTS } from '../../src/quest/goal-check.ts';
import { kindOfGoal, predictionOf } from '../../src/quest/goal.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { FakeClock, rightPrediction } from '../support/quest-fixtures.ts';
import { challengeDifference } from '../support/challenge-render.ts';
import { tracerRun } from '../support/code-lab-run.ts';

/**
 * Every level in levels/index.json is valid and solved by its own solutions, headless, as
 * Learn Git Branching's levels.spec.js does: each task's solution goes through the real
 * reducer (the store) and the real quest engine, in the level's order, and must complete
 * that task as done by the learner. A task that is already complete before its solution
 * runs would complete itself in the game; that fails too. The level's and tasks' declared
 * views are applied as the game applies them (task-views.ts), and a view must not do its
 * task's work: after it, the task's goal must still be unmet. A challenge's render is
 * measured as the app's challenge referee measures it (rendered in-process here), and the
 * comparison dispatched: a solution cannot report its own closeness.
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const readLevelFile = (name: string) => (existsSync(new URL(name, levelsFolder)) ? readFileSync(new URL(name, levelsFolder), 'utf8') : undefined);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), readLevelFile);

describe('levels/index.json', () => {
  it('is valid', () => {
    expect(catalog.errors).toEqual([]);
  });
});

for (const chapter of catalog.chapters) {
  describe(`chapter ${chapter.id}`, () => {
    for (const entry of chapter.entries) {
      it(`${entry.id} is valid and solved by its solutions`, async () => {
        if (!entry.ok) throw new Error(`levels/${entry.id}.level.json is broken:\n${entry.errors.map(issueLine).join('\n')}`);
        const { level } = entry;
        const clock = new FakeClock();
        // Every level is open: each one is tested on its own.
        const engine = new QuestEngine({ catalog: { chapters: [{ ...chapter, entries: [entry] }], errors: [] }, progress: newProgress(clock), clock });
        const opened = engine.openLevel(level.id);
        if (!opened.ok) throw new Error(`could not open ${level.id}: ${opened.reason}`);
        const store = new Store(initialState(opened.scene));
        store.subscribe(engine.observe);
        store.dispatch({ type: 'scene.loaded', scene: opened.scene });
        const views = new TaskViews();
        const applyView = (action: ReturnType<TaskViews['opened']>) => {
          if (action) expect(store.dispatch(action), 'the declared view was refused').toBeUndefined();
        };
        applyView(views.opened(level, engine.level?.current?.task ?? null));

        const statusOf = (taskId: string) => engine.level?.tasks.find((view) => view.task.id === taskId)?.status;
        for (const task of level.tasks) {
          applyView(views.changed(level, engine.level?.current?.task ?? null));
          expect(statusOf(task.id), `task "${task.id}" completed before its solution ran`).toMatch(/^(current|open)$/);
          if (kindOfGoal(task.goal) === 'do') expect(checkGoal(task.goal, store.state, NO_EVENTS), `task "${task.id}" is done by its view`).toBe(false);
          const prediction = predictionOf(task.goal);
          if (prediction) expect(engine.predict(task.id, rightPrediction(prediction))).toEqual({ correct: true });
          else if (kindOfGoal(task.goal) === 'info') expect(engine.next(), `info step "${task.id}" was not the current task`).toBe(true);
          for (const action of task.solution ?? []) {
            expect(action.type, `task "${task.id}": only the app compares a challenge's pictures`).not.toBe('challenge.compared');
            expect(store.dispatch(action), `task "${task.id}": ${action.type} was refused`).toBeUndefined();
            if (task.goal.kind === 'challenge' && action.type === 'render.finished') {
              const difference = await challengeDifference(level.scene, task.goal, store.state.scene);
              expect(store.dispatch({ type: 'challenge.compared', difference, renders: 1, changes: 0, rays: 0 })).toBeUndefined();
            }
          }
          // A code lab has no solution: the tracer's own function, graded on the level's cases as the app grades the learner's, must pass them.
          if (task.goal.kind === 'code') expect(store.dispatch(tracerRun(task.goal))).toBeUndefined();
          expect(statusOf(task.id), `task "${task.id}" was not completed by its solution`).toBe('done');
          // A prediction is explained once the task that shows its result is done; then the learner continues.
          const revealing = engine.level?.revealing;
          if (revealing) {
            expect(kindOfGoal(task.goal), `prediction "${revealing.task.id}" was explained before anything showed its result`).toBe('do');
            expect(engine.continueAfterReveal(revealing.task.id)).toBe(true);
          }
        }
        expect(engine.level?.passed).toBe(true);
        expect(engine.level?.points).toBe(engine.level?.maxPoints);
      });
    }
  });
}
