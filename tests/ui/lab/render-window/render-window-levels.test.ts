import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { TaskViews } from '../../../../src/app/task-views.ts';
import { initialState } from '../../../../src/lab-state/lab-state.ts';
import { Store } from '../../../../src/lab-state/store.ts';
import { kindOfGoal, predictionOf } from '../../../../src/quest/goal.ts';
import { loadLevels } from '../../../../src/quest/level-index.ts';
import { newProgress } from '../../../../src/quest/progress.ts';
import { QuestEngine } from '../../../../src/quest/quest-engine.ts';
import { renderWindowInTheWay, type GuideAndLook } from '../../../../src/ui/lab/render-window/render-window-in-the-way.ts';
import { FakeClock, rightPrediction } from '../../../support/quest-fixtures.ts';

/**
 * Issue 37 (2): "Render the image and zoom in" — in levels 9, 10 and 11 the render window
 * closed as soon as the render was done. Each level is played by its own solutions through
 * the real engine, store and task views (as tests/quest/levels-solvable.test.ts does); after
 * every render the window counts as open, and the lab's rule says at which task it closes.
 * No hint is asked for, so no ring closes it: only a task whose declared view needs the 3D
 * view (frames something in it, or looks through the camera) may.
 */

const levelsFolder = new URL('../../../../levels/', import.meta.url);
const readLevelFile = (name: string) => (existsSync(new URL(name, levelsFolder)) ? readFileSync(new URL(name, levelsFolder), 'utf8') : undefined);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), readLevelFile);

/** The tasks at whose start an open render window closes, playing level `id` through. */
function closesAt(id: string): { task: string; needs3d: boolean }[] {
  const chapter = catalog.chapters.find((candidate) => candidate.entries.some((entry) => entry.id === id))!;
  const entry = chapter.entries.find((candidate) => candidate.id === id)!;
  if (!entry.ok) throw new Error(`${id} is broken`);
  const { level } = entry;
  const clock = new FakeClock();
  const engine = new QuestEngine({ catalog: { chapters: [{ ...chapter, entries: [entry] }], errors: [] }, progress: newProgress(clock), clock });
  const opened = engine.openLevel(id);
  if (!opened.ok) throw new Error(`could not open ${id}`);
  const store = new Store(initialState(opened.scene));
  store.subscribe(engine.observe);
  store.dispatch({ type: 'scene.loaded', scene: opened.scene });
  const views = new TaskViews();
  const apply = (action: ReturnType<TaskViews['opened']>) => action && store.dispatch(action);
  apply(views.opened(level, engine.level?.current?.task ?? null));

  let open = false;
  let seen: GuideAndLook = { ring: null, look: store.state.look };
  const closes: { task: string; needs3d: boolean }[] = [];
  /** What the lab does on its next update: close the window if the game now needs the 3D view. */
  const labUpdates = () => {
    const now = { ring: null, look: store.state.look };
    if (open && renderWindowInTheWay(seen, now, () => true)) {
      const current = engine.level?.current?.task;
      closes.push({ task: current?.id ?? '?', needs3d: current?.view?.frame !== undefined || current?.view?.throughCamera === true });
      open = false;
    }
    seen = now;
  };
  for (const task of level.tasks) {
    apply(views.changed(level, engine.level?.current?.task ?? null));
    labUpdates();
    const prediction = predictionOf(task.goal);
    if (prediction) engine.predict(task.id, rightPrediction(prediction));
    else if (kindOfGoal(task.goal) === 'info') engine.next();
    for (const action of task.solution ?? []) {
      store.dispatch(action);
      if (action.type === 'render.finished') open = true;
      labUpdates();
    }
    const revealing = engine.level?.revealing;
    if (revealing) engine.continueAfterReveal(revealing.task.id);
    labUpdates();
  }
  return closes;
}

describe('the render window after a render task', () => {
  it('closes in level 9 only when the debugger task frames the lamp and the balls, whose pixels it asks to click', () => {
    expect(closesAt('09-attenuation')).toEqual([{ task: 'debug-attenuation', needs3d: true }]);
  });

  it('closes in level 10 only when "Inside the umbra" frames pixel 4,4\'s shadow rays, after the prediction is explained', () => {
    expect(closesAt('10-area-lights')).toEqual([{ task: 'umbra-pixel', needs3d: true }]);
  });

  it('closes in level 11 only when the nine-rays prediction looks through the camera', () => {
    expect(closesAt('11-anti-aliasing')).toEqual([{ task: 'predict-mix-share', needs3d: true }]);
  });

  it('closes in no level for a task that moves nothing in the 3D view', () => {
    const ids = catalog.chapters.flatMap((chapter) => chapter.entries.map((entry) => entry.id));
    const wrongly = ids.flatMap((id) =>
      closesAt(id)
        .filter((close) => !close.needs3d)
        .map((close) => `${id}/${close.task}`),
    );
    expect(wrongly).toEqual([]);
  });
});
