import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { assignmentProgressKey } from '../../src/classroom/assignment-id.ts';
import { conceptTestKey } from '../../src/classroom/concept-test/concept-test-store.ts';
import { surveyKey } from '../../src/classroom/survey-store.ts';
import { QuestSession } from '../../src/app/quest-session.ts';
import { sessionContextKey } from '../../src/app/session-context.ts';
import { deleteAssignmentData } from '../../src/app/withdraw-data.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { MemoryStorage, PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]);
const assignment: Assignment = {
  version: 1,
  title: 'Lesson 2',
  levels: ['first', 'second'],
  requiredTasks: {},
  otherLevels: 'hidden',
  locale: 'en',
  askParticipantCode: true,
  survey: 'default',
};

describe('withdraw and delete my data', () => {
  it("deletes the assignment's progress, session record, survey and backups, and nothing else", () => {
    const storage = new MemoryStorage();
    const key = assignmentProgressKey(assignment);
    for (const stored of [
      key,
      sessionContextKey(key),
      surveyKey(key),
      conceptTestKey(key),
      `${key}.backup.2026-01-01T00:00:00.000Z`,
      `${surveyKey(key)}.backup.2026-01-02T00:00:00.000Z`,
      `${conceptTestKey(key)}.backup.2026-01-03T00:00:00.000Z`,
    ])
      storage.setItem(stored, '{}');
    storage.setItem(PROGRESS_KEY, 'free play');
    storage.setItem('rtq.theme', 'dark');
    expect(deleteAssignmentData(storage, key)).toEqual({ progress: true, session: true, survey: true, conceptTest: true, backups: 3, failed: [] });
    expect(storage.length).toBe(2);
    expect(storage.getItem(PROGRESS_KEY)).toBe('free play');
    expect(deleteAssignmentData(storage, key)).toEqual({ progress: false, session: false, survey: false, conceptTest: false, backups: 0, failed: [] });
  });

  it('leaves nothing behind when the session stops saving first and then goes on (an idle hint, leaving the page)', () => {
    const storage = new MemoryStorage();
    const store = new Store(initialState(defaultScene()));
    const session = new QuestSession({ store, catalog, storage, assignment, clock: new FakeClock() });
    session.setParticipantCode('A17');
    session.start();
    store.dispatch({ type: 'view.orbited' });
    session.survey.submit({ survey: 'default', submittedAt: '2026-01-01T00:00:00.000Z', answers: { feedback: 'fine' } });
    const key = session.progressKey;
    expect(storage.getItem(key)).not.toBeNull();
    session.stopSaving();
    expect(deleteAssignmentData(storage, key)).toMatchObject({ progress: true, session: true, survey: true });
    store.dispatch({ type: 'render.started' });
    session.flush();
    expect([key, sessionContextKey(key), surveyKey(key)].map((stored) => storage.getItem(stored))).toEqual([null, null, null]);
    // The next visit starts afresh and asks for a code again.
    const next = new QuestSession({ store: new Store(initialState(defaultScene())), catalog, storage, assignment, clock: new FakeClock() });
    expect(next.needsParticipantCode).toBe(true);
    expect(next.engine.points).toBe(0);
  });
});
