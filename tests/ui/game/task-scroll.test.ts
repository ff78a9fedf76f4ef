// Where the task column scrolls: a level that opens opens at its title (issue 37: "each new
// level opens with its title and intro scrolled out of sight"); within a level, the current
// task or a prediction being revealed is brought into view when it changes.
import { describe, expect, it } from 'vitest';
import { taskScroll } from '../../../src/ui/game/task-scroll.ts';

describe('the task column’s scroll', () => {
  it('goes to the top when a level opens: the first one, the next one, or one reopened from the map', () => {
    expect(taskScroll({ level: null, task: null }, { level: 'first-rays', task: 'orbit' })).toEqual({ kind: 'top' });
    expect(taskScroll({ level: 'first-rays', task: 'last' }, { level: 'shadows', task: 'orbit' })).toEqual({ kind: 'top' });
    // The same first task id in another level is still a new level.
    expect(taskScroll({ level: 'first-rays', task: 'orbit' }, { level: 'shadows', task: 'orbit' })).toEqual({ kind: 'top' });
  });

  it('brings the new current task into view within a level', () => {
    expect(taskScroll({ level: 'shadows', task: 'orbit' }, { level: 'shadows', task: 'select' })).toEqual({ kind: 'task', task: 'select' });
  });

  it('brings a prediction being revealed into view, and the task after it once the learner continues', () => {
    // The panel passes the revealed prediction's id while it is open, the current task's after.
    expect(taskScroll({ level: 'shadows', task: 'render' }, { level: 'shadows', task: 'predict' })).toEqual({ kind: 'task', task: 'predict' });
    expect(taskScroll({ level: 'shadows', task: 'predict' }, { level: 'shadows', task: 'render' })).toEqual({ kind: 'task', task: 'render' });
  });

  it('stays where the learner scrolled when nothing new is shown', () => {
    expect(taskScroll({ level: 'shadows', task: 'select' }, { level: 'shadows', task: 'select' })).toEqual({ kind: 'stay' });
    // Every task done: no current task to show.
    expect(taskScroll({ level: 'shadows', task: 'select' }, { level: 'shadows', task: null })).toEqual({ kind: 'stay' });
    // The map or the free lab: no level.
    expect(taskScroll({ level: 'shadows', task: 'select' }, { level: null, task: null })).toEqual({ kind: 'stay' });
  });
});
