import { isUuid, PARTICIPANT_CODE } from '../classroom/learner-identity.ts';
import { writeBackup, type KeyValueStorage } from '../quest/saved-backups.ts';
import { isRecord } from '../util/is-record.ts';
import { readJson } from '../util/read-json.ts';

/**
 * The participant code and the playthrough's attempt id, kept next to the progress under
 * `<progress key>.context`, where the classroom's exports read them.
 *
 * A damaged record is never passed over in silence: what can still be read of it is kept
 * (each field on its own, even from text that is no longer JSON), the rest is named, and the
 * text is backed up like damaged progress (saved-backups.ts), for the Menu to offer.
 */

/** What the session keeps besides progress, for the classroom's exports. */
export interface SessionContext {
  participantCode: string | null;
  /** This playthrough's random id (learner-identity.ts); null only in a context saved before attempts had ids. */
  attemptId: string | null;
}

export type ContextField = 'participant-code' | 'attempt';

/** A record that could not be read as it was. */
export interface ContextDamage {
  /** The fields that could not be read (they start again: the code is asked, a new attempt begins). */
  lost: ContextField[];
  /** The text as it was, for a download. */
  raw: string;
  /** Where it was backed up, or null when there was no room (then it is held: not written over). */
  backupKey: string | null;
}

export type LoadedContext = { context: SessionContext; damage: ContextDamage | null };

export function sessionContextKey(progressKey: string): string {
  return `${progressKey}.context`;
}

/** The participant code and attempt id saved with the progress under `progressKey` (what can be read of them). */
export function readSessionContext(storage: KeyValueStorage, progressKey: string): SessionContext {
  try {
    const raw = storage.getItem(sessionContextKey(progressKey));
    return raw === null ? empty() : readContextText(raw).context;
  } catch {
    return empty();
  }
}

/** The saved record, with what could not be read of it backed up and named. */
export function loadSessionContext(storage: KeyValueStorage, progressKey: string, wallMs: number): LoadedContext {
  const key = sessionContextKey(progressKey);
  let raw: string | null;
  try {
    raw = storage.getItem(key);
  } catch {
    return { context: empty(), damage: null }; // the progress store reports storage that cannot be read
  }
  if (raw === null) return { context: empty(), damage: null };
  const read = readContextText(raw);
  if (!read.damaged) return { context: read.context, damage: null };
  return { context: read.context, damage: { lost: read.lost, raw, backupKey: writeBackup(storage, key, raw, wallMs) } };
}

type ContextRead = { context: SessionContext; damaged: boolean; lost: ContextField[] };

/**
 * Each field on its own: from the JSON when it parses, else from the text around its name
 * (a record cut short keeps its code). A field that is absent or null was never set (a
 * context from before attempt ids): not damage.
 */
export function readContextText(raw: string): ContextRead {
  const json = readJson(raw);
  const fields = json.ok && isRecord(json.value) ? json.value : null;
  const code = fields ? fieldOf(fields, 'participantCode') : fieldIn(raw, 'participantCode');
  const attempt = fields ? fieldOf(fields, 'attemptId') : fieldIn(raw, 'attemptId');
  const codeOk = code === null || (typeof code === 'string' && PARTICIPANT_CODE.test(code));
  const attemptOk = attempt === null || isUuid(attempt);
  const lost: ContextField[] = [...(codeOk ? [] : ['participant-code' as const]), ...(attemptOk ? [] : ['attempt' as const])];
  return {
    context: { participantCode: codeOk ? (code as string | null) : null, attemptId: attemptOk ? (attempt as string | null) : null },
    damaged: fields === null || lost.length > 0,
    lost,
  };
}

/** The field's value; null when absent or null. */
function fieldOf(fields: Record<string, unknown>, name: string): unknown {
  return fields[name] ?? null;
}

/** The string after `"name":` in text that is not JSON; undefined (damage) when it cannot be found. */
function fieldIn(raw: string, name: string): string | null | undefined {
  const found = new RegExp(`"${name}"\\s*:\\s*(null|"([^"\\\\]*)")`).exec(raw);
  if (!found) return undefined;
  return found[1] === 'null' ? null : found[2];
}

function empty(): SessionContext {
  return { participantCode: null, attemptId: null };
}
