import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { assignmentProgressKey } from '../../src/classroom/assignment-id.ts';
import { surveyKey } from '../../src/classroom/survey-store.ts';
import { QuestSession } from '../../src/app/quest-session.ts';
import { sessionContextKey } from '../../src/app/session-context.ts';
import { saveProblemReason, saveProblemText } from '../../src/i18n/progress-problem-text.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import { refusingStorage, type KeyValueStorage } from '../../src/quest/saved-backups.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';
import { QuotaStorage } from '../support/quota-storage.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]);

function open(storage: KeyValueStorage, assignment: Assignment | null = null, clock = new FakeClock()) {
  const store = new Store(initialState(defaultScene()));
  const session = new QuestSession({ store, catalog, storage, assignment, clock });
  return { store, session, clock };
}

const eventIds = (session: QuestSession) => session.engine.progress.log.events.map((event) => event.id);
const saved = (storage: KeyValueStorage, key = PROGRESS_KEY) => JSON.parse(storage.getItem(key) ?? 'null');

/** A played first level: its first task done (10 points). */
function played(storage: KeyValueStorage) {
  const opened = open(storage);
  opened.session.start();
  opened.store.dispatch({ type: 'view.orbited' });
  return opened;
}

describe('saving into a full storage', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('says a failed save, keeps everything in memory, and the next save that fits writes it all', () => {
    const storage = new QuotaStorage(200_000);
    const { session, store } = played(storage);
    expect(session.saveProblem).toBeNull();
    storage.fill(20);
    session.engine.askHint('predict');
    store.dispatch({ type: 'render.finished', ms: 30 });
    expect(session.saveProblem).toBe('storage-full');
    expect(saveProblemText('storage-full')).toMatch(
      /^The browser's storage is full, so progress is not saved\. It is kept while this page is open and saved as soon as there is room: export it \(Menu\) to be safe\.$/,
    );
    const inMemory = eventIds(session);
    expect(saved(storage).log.events.length).toBeLessThan(inMemory.length);

    storage.removeItem('filler');
    store.dispatch({ type: 'render.started' }); // the next change saves
    expect(session.saveProblem).toBeNull();
    const reloaded = open(storage).session;
    expect(reloaded.engine.points).toBe(session.engine.points);
    expect(new Set(eventIds(reloaded))).toEqual(new Set([...eventIds(session), ...eventIds(reloaded)]));
    for (const id of inMemory) expect(eventIds(reloaded)).toContain(id);
  });

  it('refuses an import that does not fit before anything changes', () => {
    const storage = new QuotaStorage(60_000);
    const { session } = played(storage);
    const before = storage.getItem(PROGRESS_KEY);
    const big = JSON.parse(session.exportText());
    big.log.events = Array.from({ length: 2000 }, (_, index) => ({ t: index, id: `big.${index}`, type: 'tab.hidden' }));
    const file = JSON.stringify(big);
    expect(file.length).toBeGreaterThan(60_000);

    expect(session.importText(file)).toEqual({ ok: false, reason: 'not-saved', kind: 'storage-full' });
    expect(saveProblemReason('storage-full')).toBe("the browser's storage has no room for it");
    expect(session.engine.points).toBe(10);
    expect(storage.getItem(PROGRESS_KEY)).toBe(before);
    expect(open(storage).session.engine.points).toBe(10);

    // One that fits replaces the progress, and is what a reload finds.
    const small = JSON.parse(session.exportText());
    small.levels = {};
    expect(session.importText(JSON.stringify(small))).toEqual({ ok: true, repaired: [] });
    expect(session.engine.points).toBe(0);
    expect(open(storage).session.engine.points).toBe(0);
  });

  it('keeps survey answers that could not be written, and writes them at the next save', () => {
    const storage = new QuotaStorage(200_000);
    const { session } = played(storage);
    const answers = { survey: 'default', submittedAt: '2025-03-01T09:30:00.000Z', answers: { rate: 4 } };
    storage.fill(10);
    expect(session.survey.submit(answers)).toBe('storage-full');
    expect(session.survey.submission).toEqual(answers);
    expect(storage.getItem(surveyKey(PROGRESS_KEY))).toBeNull();

    storage.removeItem('filler');
    session.flush(); // leaving the page, or any later change
    expect(session.saveProblem).toBeNull();
    expect(JSON.parse(storage.getItem(surveyKey(PROGRESS_KEY)) ?? 'null')).toEqual(answers);
    expect(open(storage).session.survey.submission).toEqual(answers);
  });

  it('does not reset progress it cannot write, and says why', () => {
    const storage = refusingStorage();
    const { session, store } = open(storage);
    session.start();
    store.dispatch({ type: 'view.orbited' });
    expect(session.saveProblem).toBe('storage-blocked');
    expect(session.reset()).toBe('storage-blocked');
    expect(session.engine.points).toBe(10);
  });
});

describe('a damaged save with storage nearly full', () => {
  /** A save with one bad event, in a storage with no room for a copy of it. */
  function nearlyFull() {
    const storage = new QuotaStorage(200_000);
    played(storage).session.dispose();
    const damaged = saved(storage);
    damaged.log.events[1].type = 'tab.exploded';
    const raw = JSON.stringify(damaged);
    storage.setItem(PROGRESS_KEY, raw);
    // Room for the progress to grow by a few events, not for a copy of it.
    storage.fill(raw.length / 2);
    return { storage, raw };
  }

  it('is not written over at load or by later saves, and can be downloaded; then saving goes on', () => {
    const { storage, raw } = nearlyFull();
    const { session, store } = open(storage);
    expect(session.problem).toMatchObject({ kind: 'repaired', backupKey: null, raw });
    expect(session.engine.points).toBe(10); // the rest is kept
    session.start();
    store.dispatch({ type: 'view.orbited' });
    expect(storage.getItem(PROGRESS_KEY)).toBe(raw);
    expect(session.saveProblem).toBe('damaged-held');

    const [held] = session.damagedSaves.all;
    expect(held).toMatchObject({ key: PROGRESS_KEY, what: 'progress', held: true, madeAt: null });
    expect(session.damagedSaves.text(PROGRESS_KEY)).toBe(raw);
    session.damagedSaves.downloaded(PROGRESS_KEY);
    session.flush();
    expect(session.saveProblem).toBeNull();
    expect(storage.getItem(PROGRESS_KEY)).not.toBe(raw);
    expect(session.damagedSaves.all).toEqual([]);
  });

  it('is backed up at the first save once there is room, and then written over', () => {
    const { storage, raw } = nearlyFull();
    const { session, store } = open(storage);
    storage.removeItem('filler');
    session.start();
    store.dispatch({ type: 'view.orbited' });
    expect(session.saveProblem).toBeNull();
    const [backup] = session.damagedSaves.all;
    expect(backup).toMatchObject({ what: 'progress', held: false, madeAt: '2025-03-01T09:00:00.000Z' });
    expect(storage.getItem(backup!.key)).toBe(raw);
  });
});

describe('damaged saves from the Menu', () => {
  it('a backup restored after a reset brings its points back', () => {
    const storage = new QuotaStorage(500_000);
    played(storage).session.dispose();
    const damaged = saved(storage);
    damaged.settings.locale = 'fr';
    storage.setItem(PROGRESS_KEY, JSON.stringify(damaged));
    const { session } = open(storage);
    expect(session.engine.points).toBe(10);
    expect(session.reset()).toBeNull();
    expect(session.engine.points).toBe(0);

    const [backup] = session.damagedSaves.all;
    expect(backup?.what).toBe('progress');
    expect(session.restoreBackup(backup!.key)).toEqual({ ok: true, repaired: ['settings.locale: must be one of en, nl, got "fr" (default)'] });
    expect(session.engine.points).toBe(10);
    expect(open(storage).session.engine.points).toBe(10);

    session.damagedSaves.delete(backup!.key);
    expect(storage.getItem(backup!.key)).toBeNull();
    expect(session.damagedSaves.all).toEqual([]);
  });

  it('a backup this version cannot read changes nothing', () => {
    const storage = new QuotaStorage(500_000);
    storage.setItem(PROGRESS_KEY, '{"kind": "ray-tracer-quest-progress", "version": 9}');
    const { session } = open(storage);
    expect(session.problem?.kind).toBe('other-version');
    const [backup] = session.damagedSaves.all;
    expect(session.restoreBackup(backup!.key)).toMatchObject({
      ok: false,
      reason: 'unreadable',
      errors: [{ path: 'version', reason: expect.objectContaining({ code: 'progressVersion' }) }],
    });
    expect(session.damagedSaves.text(backup!.key)).toBe('{"kind": "ray-tracer-quest-progress", "version": 9}');
  });
});

describe('a damaged session record', () => {
  const assignment: Assignment = {
    version: 1,
    title: 'Lesson 3',
    levels: ['first'],
    requiredTasks: { first: ['orbit'] },
    otherLevels: 'hidden',
    locale: 'en',
    askParticipantCode: true,
    survey: null,
  };
  const key = sessionContextKey(assignmentProgressKey(assignment));
  const attempt = '0f8fad5b-d9cb-469f-a165-70867728950e';

  it('keeps what can be read of it, even when it is no longer JSON', () => {
    const storage = new QuotaStorage(100_000);
    storage.setItem(key, `{"participantCode":"A17","attemptId":"${attempt}"`);
    const { session } = open(storage, assignment);
    expect(session.context).toEqual({ participantCode: 'A17', attemptId: attempt });
    expect(session.needsParticipantCode).toBe(false);
    expect(session.contextDamage).toMatchObject({ lost: [], backupKey: `${key}.backup.2025-03-01T09:00:00.000Z` });
  });

  it('names what it lost, asks for the code again, keeps the record to download or restore', () => {
    const storage = new QuotaStorage(100_000);
    const raw = `{"participantCode": 17, "attemptId": "${attempt}x"}`;
    storage.setItem(key, raw);
    const { session } = open(storage, assignment);
    expect(session.contextDamage).toMatchObject({ lost: ['participant-code', 'attempt'], raw });
    expect(session.needsParticipantCode).toBe(true);
    expect(session.context.attemptId).not.toBe(`${attempt}x`); // a new attempt, said
    const [backup] = session.damagedSaves.all;
    expect(backup).toMatchObject({ what: 'session', held: false });
    expect(session.damagedSaves.text(backup!.key)).toBe(raw);
    // Nothing of it can be read: a restore changes nothing.
    expect(session.restoreBackup(backup!.key)).toMatchObject({ ok: false, reason: 'unreadable' });
  });

  it('a restored record brings its code and attempt back, and the start goes on', () => {
    const storage = new QuotaStorage(100_000);
    storage.setItem(key, `{"participantCode":"B2","attemptId":"${attempt}","extra":`);
    const { session } = open(storage, assignment);
    expect(session.context.participantCode).toBe('B2');
    // The learner played on with another code, then restores the damaged record.
    session.setParticipantCode('C3');
    const [backup] = session.damagedSaves.all;
    expect(session.restoreBackup(backup!.key)).toEqual({ ok: true, repaired: [] });
    expect(session.context).toEqual({ participantCode: 'B2', attemptId: attempt });
    expect(JSON.parse(storage.getItem(key) ?? 'null')).toEqual({ participantCode: 'B2', attemptId: attempt });
  });
});

describe('leaving the page', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  /** A page's document and window as the session listens to them (events only). */
  function page() {
    const window = new EventTarget();
    const document = Object.assign(new EventTarget(), { visibilityState: 'visible', defaultView: window });
    return { window, document, hide: () => ((document.visibilityState = 'hidden'), document.dispatchEvent(new Event('visibilitychange'))) };
  }

  it('saves a sandbox edit still being dragged on pagehide and when the tab is hidden', () => {
    const storage = new QuotaStorage(200_000);
    const { session, store } = open(storage);
    const { window, document, hide } = page();
    const detach = session.attach(document as unknown as Document);
    session.openFreeLab();
    store.dispatch({ type: 'object.added', shape: 'sphere' });
    const id = store.state.scene.objects.at(-1)!.id;
    store.dispatch({ type: 'object.changed', id, changes: { position: [1, 1, 1] } }, { live: true });
    expect(saved(storage).sandbox.objects.at(-1).position).not.toEqual([1, 1, 1]);
    window.dispatchEvent(new Event('pagehide'));
    expect(saved(storage).sandbox.objects.at(-1).position).toEqual([1, 1, 1]);

    store.dispatch({ type: 'object.changed', id, changes: { position: [2, 2, 2] } }, { live: true });
    hide();
    expect(saved(storage).sandbox.objects.at(-1).position).toEqual([2, 2, 2]);
    detach();
  });

  it('tries a failed save again on pagehide', () => {
    const storage = new QuotaStorage(200_000);
    const { session, store } = played(storage);
    const { window, document } = page();
    const detach = session.attach(document as unknown as Document);
    storage.fill(10);
    store.dispatch({ type: 'render.finished', ms: 30 });
    expect(session.saveProblem).toBe('storage-full');
    storage.removeItem('filler');
    window.dispatchEvent(new Event('pagehide'));
    expect(session.saveProblem).toBeNull();
    expect(saved(storage).log.events.map((event: { id: string }) => event.id)).toEqual(eventIds(session));
    detach();
  });
});
