import { describe, expect, it } from 'vitest';
import { QuestSession } from '../../src/app/quest-session.ts';
import { levelPreviewHash, previewAssignment, previewedLevelId } from '../../src/classroom/level-preview.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { playableLevels } from '../../src/quest/level-index.ts';
import { MemoryStorage } from '../../src/quest/progress-store.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second'), levelWithId('third')] }]);
const levels = playableLevels(catalog);

describe("a teacher's preview of one level", () => {
  it('reads the level id back from its address', () => {
    expect(previewedLevelId(levelPreviewHash('04-shadows'))).toBe('04-shadows');
    expect(previewedLevelId('#/preview/')).toBeNull();
    expect(previewedLevelId('#/teacher')).toBeNull();
    expect(previewedLevelId('#/preview/%E0%A4%A')).toBeNull();
  });

  it('opens a level that free play keeps locked, with its own mandatory tasks required', () => {
    const third = levels[2];
    const free = new QuestSession({ store: new Store(initialState(defaultScene())), catalog, storage: new MemoryStorage(), clock: new FakeClock() });
    expect(free.engine.levelStatus(third.id)).toBe('locked');

    const assignment = previewAssignment(third, 'nl');
    expect(assignment).toMatchObject({ levels: ['third'], otherLevels: 'hidden', askParticipantCode: false, survey: null, locale: 'nl' });
    const preview = new QuestSession({
      store: new Store(initialState(defaultScene())),
      catalog,
      storage: new MemoryStorage(),
      assignment,
      clock: new FakeClock(),
    });
    expect(preview.start()).toEqual({ kind: 'level', id: 'third' });
    expect(assignment.requiredTasks.third).toEqual(third.tasks.filter((task) => task.mandatory).map((task) => task.id));
    expect(assignment.requiredTasks.third.length).toBeGreaterThan(0);
  });
});
