import { issueLine } from '../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { reduce } from '../../src/lab-state/lab-reducer.ts';
import { parseLevel } from '../../src/quest/level-schema.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { catalogOf, FakeClock, levelFile } from '../support/quest-fixtures.ts';

type Json = Record<string, unknown>;

function errorsOf(change: (level: Json & { tasks: Json[] }) => void): string[] {
  const result = parseLevel(levelFile(change));
  return result.ok ? [] : result.errors.map(issueLine);
}

describe('a declared view in a level file', () => {
  it("frames the scene's things, chooses a pixel and sets ray options", () => {
    const result = parseLevel(
      levelFile((level) => {
        level.view = { frame: ['ball', 'lamp', 'camera'], from: [1, 1, 1] };
        level.tasks[0].view = { frame: ['pixel-rays'], pixel: [3, 2], rays: { hideNoHit: true } };
      }),
    );
    if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
    expect(result.level.view?.frame).toEqual(['ball', 'lamp', 'camera']);
    expect(result.level.tasks[0].view).toEqual({ frame: ['pixel-rays'], pixel: [3, 2], rays: { hideNoHit: true } });
  });

  it('names only what the scene has, and pixels inside its screen', () => {
    expect(errorsOf((level) => (level.view = { frame: ['ball', 'teapot'] }))).toEqual([
      'view.frame[1]: must be one of camera, pixel-rays, ball, lamp, rays:<column>,<row>, got "teapot"',
    ]);
    expect(errorsOf((level) => (level.view = { frame: ['ball', 'rays:3,2', 'rays:4,0'] }))).toEqual([
      'view.frame[2]: "4,0" must be "column,row" inside the 4×3 screen, counting from 0',
    ]);
    expect(errorsOf((level) => (level.tasks[0].view = { pixel: [4, 0] }))).toEqual([
      'tasks[0].view.pixel: "4,0" must be "column,row" inside the 4×3 screen, counting from 0',
    ]);
  });

  it("frames a pixel's rays only with the pixel it chooses", () => {
    expect(errorsOf((level) => (level.tasks[0].view = { frame: ['pixel-rays'] }))).toEqual([
      'tasks[0].view.frame: "pixel-rays" needs the view to choose its pixel ("pixel": [column, row])',
    ]);
  });

  it('refuses unknown ray options, a zero direction, and framing while looking through the camera', () => {
    const errors = errorsOf((level) => {
      level.view = { rays: { glow: true } };
      level.tasks[0].view = { frame: ['ball'], from: [0, 0, 0] };
      level.tasks[2].view = { frame: ['ball'], throughCamera: true };
    });
    expect(errors.join('\n')).toMatch(/view\.rays: unknown field "glow"/);
    expect(errors.join('\n')).toMatch(/tasks\[2\]\.view\.throughCamera: a view either frames things or looks through the camera, not both/);
    expect(errors.join('\n')).toMatch(/tasks\[0\]\.view\.from: must be a direction, not \[0, 0, 0\]/);
  });

  it('is no goal and no solution step: the app applies it, the learner does not', () => {
    expect(errorsOf((level) => (level.tasks[0].goal = { event: 'view.applied' })).join('\n')).toMatch(
      /tasks\[0\]\.goal\.event: a level's own view is applied by the app/,
    );
    expect(errorsOf((level) => (level.tasks[0].solution = [{ type: 'view.applied', view: { pixel: [0, 0] } }]))).toEqual([
      'tasks[0].solution[0]: a view is the task\'s "view", not a step of its solution',
    ]);
  });
});

describe('applying a view', () => {
  const scene = (parseLevel(levelFile()) as { ok: true; level: { scene: ReturnType<typeof initialState>['scene'] } }).level.scene;

  it('chooses its pixel and sets its ray options over the others', () => {
    const state = { ...initialState(scene), rays: { ...initialState(scene).rays, transparency: 0.5 } };
    const { state: next, error } = reduce(state, { type: 'view.applied', view: { pixel: [1, 2], rays: { hideNoHit: true } } });
    expect(error).toBeUndefined();
    expect(next.selectedPixel).toEqual([1, 2]);
    expect(next.rays).toMatchObject({ hideNoHit: true, transparency: 0.5 });
  });

  it('leaves out a pixel the screen no longer has, and keeps the rest', () => {
    const { state: next, error } = reduce(initialState(scene), { type: 'view.applied', view: { pixel: [9, 9], rays: { hideNoHit: true } } });
    expect(error).toBeUndefined();
    expect(next.selectedPixel).toBeNull();
    expect(next.rays.hideNoHit).toBe(true);
  });

  it('counts for no task: not even an event goal on the state it sets', () => {
    const clock = new FakeClock();
    const catalog = catalogOf([{ id: 'test', levels: [levelFile((level) => (level.tasks[0].goal = { event: 'rays.changed' }))] }]);
    const engine = new QuestEngine({ catalog, progress: newProgress(clock), clock });
    const opened = engine.openLevel('test-level');
    if (!opened.ok) throw new Error(opened.reason);
    const state = initialState(opened.scene);
    engine.observe(state, { type: 'scene.loaded', scene: opened.scene });
    const viewed = reduce(state, { type: 'view.applied', view: { rays: { hideNoHit: true } } }).state;
    engine.observe(viewed, { type: 'view.applied', view: { rays: { hideNoHit: true } } });
    expect(engine.level?.current?.task.id).toBe('orbit');
    engine.observe(viewed, { type: 'rays.changed', changes: { hideNoHit: false } });
    expect(engine.level?.tasks[0].status).toBe('done');
  });
});
