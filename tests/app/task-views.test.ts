import { issueLine } from '../../src/util/issue.ts';
import { describe, expect, it } from 'vitest';
import { combineViews, TaskViews } from '../../src/app/task-views.ts';
import { parseLevel, type Level } from '../../src/quest/level-schema.ts';
import { levelFile } from '../support/quest-fixtures.ts';

function level(): Level {
  const result = parseLevel(
    levelFile((file) => {
      file.view = { frame: ['ball', 'camera'], rays: { hideNoHit: true } };
      file.tasks[0].view = { pixel: [1, 1] };
      file.tasks[2].view = { frame: ['lamp'], rays: { transparency: 0.4 } };
    }),
  );
  if (!result.ok) throw new Error(result.errors.map(issueLine).join('\n'));
  return result.level;
}

describe('which declared view is applied when', () => {
  it("opens a level with its view and its first task's together, as one action", () => {
    const views = new TaskViews();
    const opened = level();
    expect(views.opened(opened, opened.tasks[0]!)).toEqual({
      type: 'view.applied',
      view: { frame: ['ball', 'camera'], pixel: [1, 1], rays: { hideNoHit: true } },
    });
  });

  it("applies a task's view once, when it becomes current; a task without one leaves the view alone", () => {
    const views = new TaskViews();
    const opened = level();
    views.opened(opened, opened.tasks[0]!);
    expect(views.changed(opened, opened.tasks[0]!)).toBeNull();
    expect(views.changed(opened, opened.tasks[1]!)).toBeNull();
    expect(views.changed(opened, opened.tasks[2]!)).toEqual({ type: 'view.applied', view: opened.tasks[2]!.view });
    expect(views.changed(opened, opened.tasks[2]!)).toBeNull();
  });

  it("ignores the game's changes while a level is opening, and starts afresh after it is left", () => {
    const views = new TaskViews();
    const opened = level();
    expect(views.changed(opened, opened.tasks[2]!)).toBeNull();
    views.opened(opened, opened.tasks[2]!);
    views.closed();
    expect(views.changed(opened, opened.tasks[2]!)).toBeNull();
    expect(views.opened(opened, opened.tasks[2]!)?.view).toMatchObject({ frame: ['lamp'] });
  });
});

describe("a task's view on top of its level's", () => {
  it("keeps the level's way of looking unless the task has its own, and merges ray options", () => {
    expect(combineViews({ frame: ['ball'], from: [0, 1, 1], rays: { hideNoHit: true } }, { pixel: [0, 0], rays: { transparency: 0.5 } })).toEqual({
      frame: ['ball'],
      from: [0, 1, 1],
      pixel: [0, 0],
      rays: { hideNoHit: true, transparency: 0.5 },
    });
    expect(combineViews({ frame: ['ball'], from: [0, 1, 1] }, { throughCamera: true })).toEqual({ throughCamera: true });
    expect(combineViews(undefined, undefined)).toBeNull();
  });
});
