import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { loadConceptBank } from '../../src/classroom/concept-test/concept-bank.ts';
import { conceptTestKey } from '../../src/classroom/concept-test/concept-test-store.ts';
import { surveyKey } from '../../src/classroom/survey-store.ts';
import { damagedSaveFileName } from '../../src/app/damaged-saves.ts';
import { QuestSession } from '../../src/app/quest-session.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import type { KeyValueStorage } from '../../src/quest/saved-backups.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';
import { QuotaStorage } from '../support/quota-storage.ts';

// The records kept next to the progress (survey-keeper.ts, concept-test-keeper.ts) when they
// are found damaged: backed up or held, listed in the Menu's damaged saves, restored from there.

// The test before is due only once its item bank is there (concept-test-due.ts).
await loadConceptBank();

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]);

function open(storage: KeyValueStorage, assignment: Assignment | null = null, clock = new FakeClock()) {
  const store = new Store(initialState(defaultScene()));
  const session = new QuestSession({ store, catalog, storage, assignment, clock });
  return { store, session, clock };
}

/** A played first level: its first task done (10 points). */
function played(storage: KeyValueStorage) {
  const opened = open(storage);
  opened.session.start();
  opened.store.dispatch({ type: 'view.orbited' });
  return opened;
}

describe('damaged survey answers', () => {
  const answers = { survey: 'default', submittedAt: '2025-03-01T09:30:00.000Z', answers: { rate: 4, say: 'fun' } };
  const key = surveyKey(PROGRESS_KEY);

  it('are backed up, what can be read is kept, and a restore brings the rest back', () => {
    const storage = new QuotaStorage(200_000);
    const raw = JSON.stringify({ ...answers, answers: { rate: 4, say: 'fun', pick: ['a'] } });
    storage.setItem(key, raw);
    const { session } = open(storage);
    expect(session.survey.damage).toMatchObject({ lost: ['answers.pick'], raw, backupKey: `${key}.backup.2025-03-01T09:00:00.000Z` });
    expect(session.survey.submission).toEqual(answers);
    // What could be read is written in its place: the next visit finds no damage (and makes no second copy).
    expect(JSON.parse(storage.getItem(key) ?? 'null')).toEqual(answers);
    expect(open(storage).session.survey.damage).toBeNull();

    const [backup] = session.damagedSaves.all;
    expect(backup).toMatchObject({ what: 'survey', held: false });
    expect(session.damagedSaves.text(backup!.key)).toBe(raw);
    expect(session.restoreBackup(backup!.key)).toEqual({ ok: true, repaired: ['answers.pick'] });
    expect(session.survey.submission).toEqual(answers);
  });

  it('that cannot be read are asked again; a restore brings back what is in the backup', () => {
    const storage = new QuotaStorage(200_000);
    const raw = JSON.stringify(answers).slice(0, -3); // cut short inside the last answer
    storage.setItem(key, raw);
    const { session } = open(storage);
    expect(session.survey.damage).toMatchObject({ cut: true, raw });
    expect(session.survey.submission).toEqual({ ...answers, answers: { rate: 4 } });

    storage.setItem(key, '{"survey": 3, "answers": {"rate": 2}}');
    const later = new FakeClock();
    later.advance(60_000);
    const again = open(storage, null, later).session;
    expect(again.survey.submission).toBeNull();
    expect(storage.getItem(key)).toBeNull(); // nothing readable: removed once backed up
    // The learner hands in the survey again, then restores the damaged answers: theirs win for the same questions.
    expect(again.survey.submit({ ...answers, answers: { rate: 5, more: 'yes' } })).toBeNull();
    const backups = again.damagedSaves.all.filter((save) => save.what === 'survey');
    expect(backups.map((save) => again.damagedSaves.text(save.key))).toEqual([raw, '{"survey": 3, "answers": {"rate": 2}}']);
    expect(again.restoreBackup(backups[0]!.key)).toEqual({ ok: true, repaired: [] });
    expect(again.survey.submission).toEqual({ ...answers, answers: { rate: 4, more: 'yes' } });
    expect(again.restoreBackup(backups[1]!.key)).toMatchObject({ ok: false, reason: 'unreadable' });
  });

  it('with no room for a copy are not written over, even by a new hand-in, until downloaded', () => {
    const storage = new QuotaStorage(200_000);
    played(storage).session.dispose();
    const raw = `{"survey":"default","submittedAt":"2025-03-01T09:30:00.000Z","answers":{"rate":4,"say":"${'a long answer '.repeat(200)}, damaged`;
    storage.setItem(key, raw);
    // Room for the progress to grow by a few events, not for a copy of the answers.
    storage.fill(raw.length / 2);
    const { session } = open(storage);
    expect(session.survey.damage).toMatchObject({ backupKey: null, raw });
    expect(session.saveProblem).toBe('damaged-held');
    expect(session.survey.submit(answers)).toBe('damaged-held');
    expect(session.survey.submission).toEqual(answers); // kept in memory
    expect(storage.getItem(key)).toBe(raw);
    expect(session.damagedSaves.all).toEqual([{ key, what: 'survey', madeAt: null, size: raw.length, held: true }]);
    expect(session.damagedSaves.text(key)).toBe(raw);

    session.damagedSaves.downloaded(key);
    session.flush();
    expect(session.saveProblem).toBeNull();
    expect(JSON.parse(storage.getItem(key) ?? 'null')).toEqual(answers);
    expect(session.damagedSaves.all).toEqual([]);
  });
});

describe('damaged concept-test answers', () => {
  const assignment: Assignment = {
    version: 1,
    title: 'T',
    levels: ['first'],
    requiredTasks: { first: ['orbit'] },
    otherLevels: 'hidden',
    locale: 'en',
    askParticipantCode: true,
    survey: null,
    conceptTest: 'a-then-b',
  };
  const pre = { form: 'A' as const, submittedAt: '2026-03-09T10:00:00.000Z', answers: { light: 'from-lamp', shadow: 'blocked' } };
  const later = (minutes: number) => {
    const clock = new FakeClock();
    clock.advance(minutes * 60_000);
    return clock;
  };

  it('are backed up and listed with the damaged saves, to download, restore or delete', () => {
    const storage = new QuotaStorage(200_000);
    const key = conceptTestKey(open(storage, assignment).session.progressKey);
    const raw = JSON.stringify({ pre: { ...pre, answers: { ...pre.answers, lens: 7 } }, post: null });
    storage.setItem(key, raw);
    const { session } = open(storage, assignment);
    // What could be read is kept and written in its place: the test before is not asked again.
    expect(session.conceptTests.answers.pre).toEqual(pre);
    expect(JSON.parse(storage.getItem(key) ?? 'null')).toEqual({ pre, post: null });

    const [backup] = session.damagedSaves.all;
    expect(backup).toEqual({
      key: `${key}.backup.2025-03-01T09:00:00.000Z`,
      what: 'concept-test',
      madeAt: '2025-03-01T09:00:00.000Z',
      size: raw.length,
      held: false,
    });
    expect(session.damagedSaves.text(backup!.key)).toBe(raw);
    expect(damagedSaveFileName(backup!)).toBe('ray-tracer-quest-damaged-concept-test-answers-2025-03-01T09-00-00.json');
    expect(session.restoreBackup(backup!.key)).toEqual({ ok: true, repaired: ['pre.lens'] });
    session.damagedSaves.delete(backup!.key);
    expect(storage.getItem(backup!.key)).toBeNull();
    expect(session.damagedSaves.all).toEqual([]);
  });

  it('restored from an older copy bring the test before back, and the start that waited for it goes on', () => {
    const storage = new QuotaStorage(200_000);
    const key = conceptTestKey(open(storage, assignment).session.progressKey);
    // A first visit finds one answer damaged (backed up at 09:00), a later one finds nothing readable (09:10).
    storage.setItem(key, JSON.stringify({ pre: { ...pre, answers: { ...pre.answers, lens: 7 } }, post: null }));
    open(storage, assignment).session.dispose();
    storage.setItem(key, '{"pre": {"form": "A", "answers": {"light": "fr');
    const { session } = open(storage, assignment, later(10));
    session.setParticipantCode('P-1');
    expect(session.start()).toEqual({ kind: 'map' });
    expect(session.conceptTests.due).toBe('pre');

    const backups = session.damagedSaves.all.filter((save) => save.what === 'concept-test');
    expect(backups.map((save) => save.madeAt)).toEqual(['2025-03-01T09:00:00.000Z', '2025-03-01T09:10:00.000Z']);
    expect(session.restoreBackup(backups[1]!.key)).toMatchObject({ ok: false, reason: 'unreadable' });
    expect(session.mode).toEqual({ kind: 'map' });
    expect(session.restoreBackup(backups[0]!.key)).toEqual({ ok: true, repaired: ['pre.lens'] });
    expect(session.conceptTests.answers).toEqual({ pre, post: null });
    expect(session.mode).toEqual({ kind: 'level', id: 'first' });
    expect(JSON.parse(storage.getItem(key) ?? 'null')).toEqual({ pre, post: null });
  });

  it('with no room for a copy are listed as held, not written over until downloaded', () => {
    const storage = new QuotaStorage(200_000);
    open(storage, assignment).session.dispose();
    const key = conceptTestKey(open(storage, assignment).session.progressKey);
    const raw = `{"pre":{"form":"A","submittedAt":"2026-03-09T10:00:00.000Z","answers":{"light":"${'a'.repeat(3000)}`;
    storage.setItem(key, raw);
    // Room for the progress to grow by a few events, not for a copy of the answers.
    storage.fill(raw.length / 2);
    const { session } = open(storage, assignment);
    expect(session.saveProblem).toBe('damaged-held');
    expect(session.damagedSaves.all).toEqual([{ key, what: 'concept-test', madeAt: null, size: raw.length, held: true }]);
    expect(session.damagedSaves.text(key)).toBe(raw);
    expect(storage.getItem(key)).toBe(raw);

    session.damagedSaves.downloaded(key);
    session.flush();
    expect(session.saveProblem).toBeNull();
    expect(JSON.parse(storage.getItem(key) ?? 'null')).toEqual({ pre: null, post: null });
    expect(session.damagedSaves.all).toEqual([]);
  });
});
