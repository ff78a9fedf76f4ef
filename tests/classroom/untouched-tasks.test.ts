import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { exportCsv } from '../../src/classroom/export-csv.ts';
import { buildExport } from '../../src/classroom/export-json.ts';
import { exportXapi } from '../../src/classroom/export-xapi.ts';
import { parseCsv } from '../../src/classroom/csv-text.ts';
import type { ExportInput } from '../../src/classroom/export-context.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import type { LabAction } from '../../src/lab-state/lab-action.ts';
import { kindOfGoal, predictionOf } from '../../src/quest/goal.ts';
import { loadLevels } from '../../src/quest/level-index.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { FakeClock, rightPrediction } from '../support/quest-fixtures.ts';

/**
 * Issue 40: optional tasks nobody touched were exported as started and unfinished, with
 * active time. A learner plays the real levels 1 and 2 through the real store and engine,
 * doing every required task by its solution and only some optional ones. Painting and
 * moving the ball (level 1) must not start "turn the box" (the store rebuilds the scene on
 * every edit); selecting pixel 2,2 (level 2) must not start "select pixel 0,0".
 */

const levelsFolder = new URL('../../levels/', import.meta.url);
const catalog = loadLevels(readFileSync(new URL('index.json', levelsFolder), 'utf8'), (name) => readFileSync(new URL(name, levelsFolder), 'utf8'));

/** The optional tasks this learner does; every other optional task is left alone. */
const DONE_OPTIONAL: Record<string, string[]> = { '01-introduction': ['pan'], '02-rays-from-the-camera': ['fly-to-camera'] };

function play(): ExportInput {
  const clock = new FakeClock();
  const engine = new QuestEngine({ catalog, progress: newProgress(clock), clock });
  for (const levelId of Object.keys(DONE_OPTIONAL)) {
    const opened = engine.openLevel(levelId);
    if (!opened.ok) throw new Error(`could not open ${levelId}: ${opened.reason}`);
    const store = new Store(initialState(opened.scene));
    store.subscribe(engine.observe);
    store.dispatch({ type: 'scene.loaded', scene: opened.scene });
    for (const task of opened.level.tasks) {
      if (task.mandatory === false && !DONE_OPTIONAL[levelId].includes(task.id)) continue;
      clock.advance(10_000);
      const prediction = predictionOf(task.goal);
      if (prediction) engine.predict(task.id, rightPrediction(prediction));
      else if (kindOfGoal(task.goal) === 'info') engine.next();
      for (const action of task.solution ?? []) store.dispatch(action as LabAction);
      const revealing = engine.level?.revealing;
      if (revealing) engine.continueAfterReveal(revealing.task.id);
    }
    expect(engine.level?.passed, `${levelId} passed`).toBe(true);
    clock.advance(20_000);
    engine.closeLevel();
  }
  return {
    progress: engine.progress,
    participant: 'P1',
    installId: '11111111-2222-4333-8444-555555555555',
    attemptId: '66666666-7777-4888-9999-aaaaaaaaaaaa',
    assignment: null,
    survey: null,
    exportedAt: '2025-03-04T10:00:00.000Z',
    appVersion: '1.0.0',
  };
}

/** Every optional task of the two levels, as `level/task`. */
function optionalTasks(): { touched: string[]; untouched: string[] } {
  const touched: string[] = [];
  const untouched: string[] = [];
  for (const entry of catalog.chapters.flatMap((chapter) => chapter.entries)) {
    if (!entry.ok || !(entry.level.id in DONE_OPTIONAL)) continue;
    for (const task of entry.level.tasks.filter((candidate) => candidate.mandatory === false)) {
      (DONE_OPTIONAL[entry.level.id].includes(task.id) ? touched : untouched).push(`${entry.level.id}/${task.id}`);
    }
  }
  return { touched, untouched };
}

describe('optional tasks nobody touched', () => {
  const input = play();
  const { touched, untouched } = optionalTasks();

  it('are the ones the issue found recorded as started', () => {
    expect(untouched).toEqual(expect.arrayContaining(['01-introduction/turn-box', '02-rays-from-the-camera/top-left-pixel']));
    expect(touched).toEqual(['01-introduction/pan', '02-rays-from-the-camera/fly-to-camera']);
  });

  it('have no row in the CSV export; the touched ones do', () => {
    const parsed = parseCsv(exportCsv(input).replace(/^\uFEFF/, ''));
    if (!parsed.ok) throw new Error(parsed.error);
    const [header, ...rows] = parsed.rows;
    const at = (name: string) => header.indexOf(name);
    const tasks = new Set(rows.map((row) => `${row[at('level')]}/${row[at('task')]}`));
    for (const task of untouched) expect(tasks, task).not.toContain(task);
    for (const task of touched) expect(tasks, task).toContain(task);
  });

  it('have no attempt in the JSON export; the touched ones do', () => {
    const tasks = new Set(buildExport(input).attempts.map((attempt) => `${attempt.level}/${attempt.task}`));
    for (const task of untouched) expect(tasks, task).not.toContain(task);
    for (const task of touched) expect(tasks, task).toContain(task);
  });

  it('have no statement in the xAPI export; the touched ones do', () => {
    const objects = new Set(exportXapi(input).map((statement) => statement.object.id));
    // A task's activity is levels/<level>/tasks/<task>; its hints and explanation are below it.
    const about = (task: string) => {
      const [level, id] = task.split('/');
      return [...objects].some((object) => object.includes(`levels/${level}/tasks/${id}`));
    };
    for (const task of untouched) expect(about(task), task).toBe(false);
    for (const task of touched) expect(about(task), task).toBe(true);
  });
});
