// The task card's tag says what the learner's assignment asks, not what the level file says:
// a task the teacher made required shows "required", one left out shows "optional".
import { afterEach, describe, expect, it } from 'vitest';
import { newProgress } from '../../src/quest/progress.ts';
import { QuestEngine } from '../../src/quest/quest-engine.ts';
import '../../src/ui/game/rt-task-card.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';
import { mount, unmountAll } from './mount.ts';

afterEach(unmountAll);

describe('the task card', () => {
  it("tags each task as the teacher's assignment has it", async () => {
    const clock = new FakeClock();
    // The test level: orbit, predict and supersample are required by the level; red-ball and zoom are optional.
    const engine = new QuestEngine({
      catalog: catalogOf([{ id: 'test', levels: [levelWithId('first')] }]),
      progress: newProgress(clock),
      clock,
      requiredTasks: { first: ['orbit', 'red-ball'] },
    });
    expect(engine.openLevel('first').ok).toBe(true);
    const tags: Record<string, string> = {};
    for (const view of engine.level!.tasks) {
      const card = await mount('rt-task-card', { task: view });
      tags[view.task.id] = card
        .shadowRoot!.querySelector('.tags')!
        .textContent!.replace(/\d+ pts/, '')
        .trim();
    }
    expect(tags).toEqual({ orbit: '', 'red-ball': 'required', predict: 'optional', supersample: 'optional', zoom: 'optional' });
  });
});
