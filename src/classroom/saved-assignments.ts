import { z } from 'zod';
import { isQuotaError, writeBackup, type KeyValueStorage } from '../quest/saved-backups.ts';
import type { Assignment } from './assignment.ts';
import { assignmentSchema } from './assignment-schema.ts';

/**
 * The teacher's assignments, kept in this browser (localStorage) so that a reload, or next
 * week's lesson, finds them again. Each is kept under an id of its own (a copy for another
 * class is another entry), with the time it was last changed.
 *
 * With the care of the learners' progress (progress-store.ts): a write that the browser
 * refuses is reported, never called kept; a list that cannot be read as it is loses only its
 * damaged entries, and the text it had is first copied to a backup key (saved-backups.ts),
 * so nothing a teacher made is written over unseen. Every write reads the list again, so
 * two open teacher pages add to it rather than replace each other's.
 */

export const SAVED_ASSIGNMENTS_KEY = 'rtq.teacher.assignments';

export interface SavedAssignment {
  /** Random, made when the assignment was started or copied: not the link's hash, which changes as it is edited. */
  id: string;
  assignment: Assignment;
  /** When it was last changed (ISO 8601, UTC). */
  savedAt: string;
}

/** Why a write did not keep the assignment: no room, or the browser does not allow storage. */
export type KeepProblem = 'storage-full' | 'storage-blocked';
export type KeepResult = { ok: true } | { ok: false; kind: KeepProblem };

/** What was read, and how many entries (or whether the whole list) could not be. */
export interface ReadShelf {
  entries: SavedAssignment[];
  /** Entries left out because they were damaged (a whole unreadable list counts as one). */
  damaged: number;
  /** Where the damaged text was copied, or null when nothing was damaged or the copy failed. */
  backupKey: string | null;
}

const entrySchema = z.strictObject({ id: z.string().min(1).max(64), assignment: assignmentSchema, savedAt: z.iso.datetime() });
const FORMAT = 'ray-tracer-quest-teacher-assignments';
const shelfSchema = z.strictObject({ format: z.literal(FORMAT), version: z.literal(1), entries: z.array(z.unknown()) });

export class AssignmentShelf {
  /** Damaged text found on reading and not yet copied away: nothing is written over it until it is. */
  private held: string | null = null;
  /** Damaged text already copied to a backup: read again, it is not copied twice. */
  private copied: string | null = null;

  constructor(
    private readonly storage: KeyValueStorage,
    private readonly wallMs: () => number = Date.now,
  ) {}

  /** Every kept assignment, the most recently changed first. */
  read(): ReadShelf {
    let raw: string | null;
    try {
      raw = this.storage.getItem(SAVED_ASSIGNMENTS_KEY);
    } catch {
      return { entries: [], damaged: 0, backupKey: null };
    }
    if (raw === null) return { entries: [], damaged: 0, backupKey: null };
    const { entries, damaged } = parseShelf(raw);
    if (damaged === 0 || raw === this.copied) return { entries: newestFirst(entries), damaged, backupKey: null };
    const backupKey = writeBackup(this.storage, SAVED_ASSIGNMENTS_KEY, raw, this.wallMs());
    if (backupKey === null) this.held = raw;
    else this.copied = raw;
    return { entries: newestFirst(entries), damaged, backupKey };
  }

  /** Keeps `assignment` under `id` (new or changed); says whether the browser stored it. */
  keep(id: string, assignment: Assignment): KeepResult {
    return this.write((entries) => [{ id, assignment, savedAt: new Date(this.wallMs()).toISOString() }, ...entries.filter((entry) => entry.id !== id)]);
  }

  /** Forgets the assignment kept under `id` (its link still works: the link is the assignment). */
  remove(id: string): KeepResult {
    return this.write((entries) => entries.filter((entry) => entry.id !== id));
  }

  private write(change: (entries: SavedAssignment[]) => SavedAssignment[]): KeepResult {
    const current = this.read();
    if (this.held !== null) {
      // A damaged list that could not be copied: try again, and write nothing over it until it is.
      if (writeBackup(this.storage, SAVED_ASSIGNMENTS_KEY, this.held, this.wallMs()) === null) return { ok: false, kind: 'storage-full' };
      this.copied = this.held;
      this.held = null;
    }
    const text = JSON.stringify({ format: FORMAT, version: 1, entries: change(current.entries) });
    try {
      this.storage.setItem(SAVED_ASSIGNMENTS_KEY, text);
      return { ok: true };
    } catch (error) {
      return { ok: false, kind: isQuotaError(error) ? 'storage-full' : 'storage-blocked' };
    }
  }
}

/** A random id for a new entry (not a secret: it only tells two kept assignments apart). */
export function newShelfId(): string {
  return Array.from(crypto.getRandomValues(new Uint8Array(8)), (byte) => byte.toString(16).padStart(2, '0')).join('');
}

function parseShelf(raw: string): { entries: SavedAssignment[]; damaged: number } {
  let json: unknown;
  try {
    json = JSON.parse(raw);
  } catch {
    return { entries: [], damaged: 1 };
  }
  const shelf = shelfSchema.safeParse(json);
  if (!shelf.success) return { entries: [], damaged: 1 };
  const entries: SavedAssignment[] = [];
  for (const candidate of shelf.data.entries) {
    const entry = entrySchema.safeParse(candidate);
    if (entry.success && !entries.some((other) => other.id === entry.data.id)) entries.push(entry.data);
  }
  return { entries, damaged: shelf.data.entries.length - entries.length };
}

function newestFirst(entries: SavedAssignment[]): SavedAssignment[] {
  return [...entries].sort((a, b) => (a.savedAt < b.savedAt ? 1 : a.savedAt > b.savedAt ? -1 : 0));
}
