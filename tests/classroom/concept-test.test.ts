import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { QuestSession } from '../../src/app/quest-session.ts';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { decodeAssignment, encodeAssignment } from '../../src/classroom/assignment-link.ts';
import { conceptAnswerRows } from '../../src/classroom/concept-test/concept-answers.ts';
import { parseConceptBank } from '../../src/classroom/concept-test/concept-bank-schema.ts';
import { conceptBankNow, formItems, loadConceptBank } from '../../src/classroom/concept-test/concept-bank.ts';
import { conceptForms } from '../../src/classroom/concept-test/concept-test-plan.ts';
import { conceptTestKey, loadConceptTest } from '../../src/classroom/concept-test/concept-test-store.ts';
import { buildExport } from '../../src/classroom/export-json.ts';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { Store } from '../../src/lab-state/store.ts';
import { MemoryStorage, PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import { newProgress } from '../../src/quest/progress.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';
import { QuotaStorage } from '../support/quota-storage.ts';
import fixture from './fixtures/concept-bank.fixture.json';

// The item bank loads apart from the first screen (concept-bank.ts).
await loadConceptBank();

const bank = (() => {
  const parsed = parseConceptBank(fixture);
  if (!parsed.ok) throw new Error(parsed.errors.join('\n'));
  return parsed.bank;
})();

describe('the concept test in an assignment', () => {
  it('ships a valid item bank with both forms', () => {
    expect(conceptBankNow()).not.toBeNull();
    expect(formItems(conceptBankNow()!, 'A').length).toBe(formItems(conceptBankNow()!, 'B').length);
  });

  it('gives A then B to everyone, or counterbalanced B first to about half, the same for one attempt id every time', () => {
    expect(conceptForms('a-then-b', 'any')).toEqual({ pre: 'A', post: 'B' });
    const ids = Array.from({ length: 400 }, (_, index) => `attempt-${index}`);
    const bFirst = ids.filter((id) => conceptForms('counterbalanced', id).pre === 'B');
    expect(bFirst.length).toBeGreaterThan(160);
    expect(bFirst.length).toBeLessThan(240);
    for (const id of ids) expect(conceptForms('counterbalanced', id)).toEqual(conceptForms('counterbalanced', id));
    expect(conceptForms('counterbalanced', bFirst[0]!)).toEqual({ pre: 'B', post: 'A' });
  });

  const base: Assignment = {
    version: 1,
    title: 'Lesson 1',
    levels: ['01-introduction'],
    requiredTasks: {},
    otherLevels: 'hidden',
    locale: 'nl',
    askParticipantCode: true,
    survey: 'default',
    classCode: '5H2',
  };

  it('opens a link made before the concept test existed, and carries the option in a new one', async () => {
    // Made by the app before this option (same link version, 1).
    const old =
      '#/a/1.eJwtzDELwjAQhuG_It8cwQouWV0cOji4SYeQnPRoSPTuUpDS_y5V9_d5F8wkyrXAdw7GlgkePanWsuvgkGmmrPB3HLo9F5OaWrQNDA5Cr8ZC6RZ0Uvhldag2kvR_hJFTorJtagzfdclwCDpdgxhHfoZi55oI3qSRgzaZ6Q2PRI_QssEh5qD6a3C6HLF-AJDWPN4';
    expect(await decodeAssignment(old)).toEqual({ ok: true, assignment: base });
    const withTest: Assignment = { ...base, conceptTest: 'counterbalanced' };
    expect(await decodeAssignment(await encodeAssignment(withTest))).toEqual({ ok: true, assignment: withTest });
    const wrong = await encodeAssignment({ ...base, conceptTest: 'sometimes' } as unknown as Assignment);
    expect(await decodeAssignment(wrong)).toMatchObject({ ok: false, kind: 'damaged' });
  });
});

describe('the concept test answers as saved and exported', () => {
  it('keeps what can be read of a damaged record, names what cannot, and backs it up', () => {
    const storage = new MemoryStorage();
    const raw = JSON.stringify({
      pre: { form: 'A', submittedAt: '2026-03-09T10:00:00.000Z', answers: { 'shadows-1a': 'right', 'shadows-2a': 7 } },
      post: { form: 'C', answers: {} },
    });
    storage.setItem(conceptTestKey(PROGRESS_KEY), raw);
    const loaded = loadConceptTest(storage, PROGRESS_KEY, 0);
    expect(loaded.answers).toEqual({ pre: { form: 'A', submittedAt: '2026-03-09T10:00:00.000Z', answers: { 'shadows-1a': 'right' } }, post: null });
    expect(loaded.damage).toMatchObject({ lost: ['pre.shadows-2a', 'post'], raw });
    expect(storage.getItem(loaded.damage!.backupKey!)).toBe(raw);
    storage.setItem(conceptTestKey('other'), '{"pre": {"form": "A", "submitted');
    expect(loadConceptTest(storage, 'other', 0)).toMatchObject({ answers: { pre: null, post: null }, damage: { lost: ['record'] } });
  });

  it('exports every answer with item, concept, form, phase, choice and whether it was right', () => {
    const answers = {
      pre: { form: 'B' as const, submittedAt: 'x', answers: { 'shadows-1b': 'wrong', 'refraction-1b': 'right' } },
      post: { form: 'A' as const, submittedAt: 'y', answers: { 'shadows-1a': 'right', gone: 'right' } },
    };
    expect(conceptAnswerRows(bank, answers)).toEqual([
      { item: 'shadows-1b', concept: 'shadows', form: 'B', phase: 'pre', choice: 'wrong', right: false },
      { item: 'refraction-1b', concept: 'refraction', form: 'B', phase: 'pre', choice: 'right', right: true },
      { item: 'shadows-1a', concept: 'shadows', form: 'A', phase: 'post', choice: 'right', right: true },
      { item: 'gone', concept: '', form: 'A', phase: 'post', choice: 'right', right: null },
    ]);
    const clock = { monotonicMs: () => 0, wallMs: () => 0 };
    const input = {
      progress: newProgress(clock),
      participant: null,
      installId: 'i',
      attemptId: 'a',
      assignment: null,
      survey: null,
      exportedAt: 'z',
      appVersion: 't',
    };
    expect(buildExport(input).conceptTest).toBeNull();
    expect(buildExport({ ...input, conceptTest: answers }).conceptTest).toMatchObject({ pre: answers.pre, post: answers.post });
  });
});

describe('the quest session with a concept test', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first')] }]);
  const assignment: Assignment = { ...catalogAssignment(), conceptTest: 'a-then-b' };
  function catalogAssignment(): Assignment {
    return {
      version: 1,
      title: 'T',
      levels: ['first'],
      requiredTasks: { first: ['orbit'] },
      otherLevels: 'hidden',
      locale: 'en',
      askParticipantCode: true,
      survey: null,
    };
  }
  const open = (storage: MemoryStorage | QuotaStorage) => {
    const store = new Store(initialState(defaultScene()));
    return { store, session: new QuestSession({ store, catalog, storage, assignment, clock: new FakeClock() }) };
  };
  const pre = { form: 'A' as const, submittedAt: '2026-03-09T10:00:00.000Z', answers: { x: 'y' } };

  it('asks for the test before after the code, starts the first level only once it is handed in, and the test after once all is passed', () => {
    const storage = new MemoryStorage();
    const { store, session } = open(storage);
    expect(session.start()).toEqual({ kind: 'map' });
    expect(session.conceptTests.due).toBe('pre');
    session.setParticipantCode('P-1');
    expect(session.mode).toEqual({ kind: 'map' });
    expect(session.engine.events.some((event) => event.type === 'level.opened')).toBe(false);
    expect(session.conceptTests.submit('pre', pre)).toBeNull();
    expect(session.mode).toEqual({ kind: 'level', id: 'first' });
    expect(session.conceptTests.due).toBeNull();
    store.dispatch({ type: 'view.orbited' });
    expect(session.allPassed).toBe(true);
    expect(session.conceptTests.due).toBe('post');
    const post = { ...pre, form: 'B' as const };
    session.conceptTests.submit('post', post);
    expect(session.conceptTests.due).toBeNull();
    expect(open(storage).session.conceptTests.answers).toEqual({ pre, post });
  });

  it('does not ask for the test before once levels were played', () => {
    const storage = new MemoryStorage();
    const first = open(storage);
    first.session.start();
    first.session.setParticipantCode('P-1');
    first.session.conceptTests.submit('pre', pre);
    expect(first.session.mode).toEqual({ kind: 'level', id: 'first' });
    storage.removeItem(conceptTestKey(first.session.progressKey));
    expect(open(storage).session.conceptTests.due).toBeNull();
  });

  it('keeps answers that could not be written, and writes them at the next save', () => {
    const storage = new QuotaStorage(200_000);
    const { session } = open(storage);
    session.setParticipantCode('P-1');
    storage.fill(10);
    expect(session.conceptTests.submit('pre', pre)).toBe('storage-full');
    expect(session.conceptTests.answers.pre).toEqual(pre);
    expect(storage.getItem(conceptTestKey(session.progressKey))).toBeNull();
    storage.removeItem('filler');
    session.flush();
    expect(JSON.parse(storage.getItem(conceptTestKey(session.progressKey)) ?? 'null')).toEqual({ pre, post: null });
  });
});
