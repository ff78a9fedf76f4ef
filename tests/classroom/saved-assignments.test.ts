import { describe, expect, it } from 'vitest';
import type { Assignment } from '../../src/classroom/assignment.ts';
import { AssignmentShelf, newShelfId, SAVED_ASSIGNMENTS_KEY } from '../../src/classroom/saved-assignments.ts';
import { listBackups, MemoryStorage, refusingStorage } from '../../src/quest/saved-backups.ts';

const lesson: Assignment = {
  version: 1,
  title: 'Ray tracing, lesson 1',
  levels: ['01-introduction', '02-rays-from-the-camera'],
  requiredTasks: {},
  otherLevels: 'hidden',
  locale: 'nl',
  askParticipantCode: true,
  survey: null,
  classCode: '5H2',
};

/** A storage whose writes fail as a full one does. */
class FullStorage extends MemoryStorage {
  override setItem(): void {
    throw new DOMException('full', 'QuotaExceededError');
  }
}

describe('the teacher page keeps assignments in the browser', () => {
  it('keeps an assignment and reads it back after a reload', () => {
    const storage = new MemoryStorage();
    let now = Date.parse('2026-12-07T08:00:00Z');
    const shelf = new AssignmentShelf(storage, () => now);
    expect(shelf.keep('a', lesson)).toEqual({ ok: true });
    now += 60_000;
    expect(shelf.keep('b', { ...lesson, title: 'Copy for 5H3', classCode: '5H3' })).toEqual({ ok: true });
    const again = new AssignmentShelf(storage).read();
    expect(again.damaged).toBe(0);
    expect(again.entries.map((entry) => [entry.id, entry.assignment.classCode])).toEqual([
      ['b', '5H3'],
      ['a', '5H2'],
    ]);
    expect(again.entries[1]).toEqual({ id: 'a', assignment: lesson, savedAt: '2026-12-07T08:00:00.000Z' });
  });

  it('changes an entry in place, and forgets a removed one', () => {
    const storage = new MemoryStorage();
    const shelf = new AssignmentShelf(storage);
    shelf.keep('a', lesson);
    shelf.keep('a', { ...lesson, title: 'Renamed' });
    expect(shelf.read().entries.map((entry) => entry.assignment.title)).toEqual(['Renamed']);
    expect(shelf.remove('a')).toEqual({ ok: true });
    expect(shelf.read().entries).toEqual([]);
  });

  it('adds to what another open teacher page kept instead of replacing it', () => {
    const storage = new MemoryStorage();
    const one = new AssignmentShelf(storage);
    const two = new AssignmentShelf(storage);
    one.read();
    two.read();
    one.keep('a', lesson);
    two.keep('b', lesson);
    expect(
      one
        .read()
        .entries.map((entry) => entry.id)
        .sort(),
    ).toEqual(['a', 'b']);
  });

  it('says when the browser refused the write, never that it kept it', () => {
    expect(new AssignmentShelf(new FullStorage()).keep('a', lesson)).toEqual({ ok: false, kind: 'storage-full' });
    expect(new AssignmentShelf(refusingStorage()).keep('a', lesson)).toEqual({ ok: false, kind: 'storage-blocked' });
  });

  it('leaves out a damaged entry, and copies the damaged text to a backup first', () => {
    const storage = new MemoryStorage();
    const shelf = new AssignmentShelf(storage, () => Date.parse('2026-12-07T08:00:00Z'));
    shelf.keep('a', lesson);
    const saved = JSON.parse(storage.getItem(SAVED_ASSIGNMENTS_KEY) ?? '');
    const damaged = JSON.stringify({ ...saved, entries: [...saved.entries, { id: 'x', assignment: { title: 3 } }] });
    storage.setItem(SAVED_ASSIGNMENTS_KEY, damaged);
    const read = shelf.read();
    expect(read.entries.map((entry) => entry.id)).toEqual(['a']);
    expect(read.damaged).toBe(1);
    expect(read.backupKey).not.toBeNull();
    expect(storage.getItem(read.backupKey ?? '')).toBe(damaged);
    // Kept again in the same millisecond: the backup is not made twice, and the write goes through.
    expect(shelf.keep('b', lesson)).toEqual({ ok: true });
    expect(listBackups(storage, [SAVED_ASSIGNMENTS_KEY])).toHaveLength(1);
  });

  it('writes nothing over a list it cannot read when the backup cannot be made', () => {
    const storage = new FullStorage();
    // MemoryStorage's own write, to put unreadable text there as an older version might have.
    MemoryStorage.prototype.setItem.call(storage, SAVED_ASSIGNMENTS_KEY, '{not json');
    const shelf = new AssignmentShelf(storage);
    expect(shelf.read()).toMatchObject({ entries: [], damaged: 1, backupKey: null });
    expect(shelf.keep('a', lesson)).toEqual({ ok: false, kind: 'storage-full' });
    expect(storage.getItem(SAVED_ASSIGNMENTS_KEY)).toBe('{not json');
  });

  it('makes ids that differ', () => {
    expect(newShelfId()).toMatch(/^[0-9a-f]{16}$/);
    expect(newShelfId()).not.toBe(newShelfId());
  });
});
