import { gotOf, issueLine, type Issue, type Reason } from '../util/issue.ts';
import { describeIssue, issuesOf } from '../scene/scene-issues.ts';
import type { QuestClock } from './event-log.ts';
import { isRecord } from '../util/is-record.ts';
import { newEpoch, newProgress, PROGRESS_KIND, PROGRESS_VERSION, progressSchema, type Progress } from './progress.ts';
import { mergeProgress } from './progress-merge.ts';
import { readJson } from '../util/read-json.ts';
import { salvageProgress } from './progress-salvage.ts';
import { isQuotaError, writeBackup, type KeyValueStorage } from './saved-backups.ts';

/**
 * Saves progress between visits (localStorage in the browser) and reads it back. Saved data
 * that cannot be used as it was never ends in a blank screen and is never lost:
 *
 * - a damaged part is left out and the rest kept (progress-salvage.ts); data that cannot be
 *   read at all (not JSON, from another app or version) gives a fresh start;
 * - either way the old text is kept under a backup key (saved-backups.ts) and handed to the
 *   UI, to offer it as a download;
 * - when there is no room for the backup, the old text stays where it is: nothing is saved
 *   over it (`save` says `damaged-held`) until it is backed up or the learner has downloaded
 *   it (`release`).
 *
 * Several tabs share one saved progress: a save merges with what is saved (progress-merge.ts)
 * instead of writing over it, and `read()` lets a tab that heard of another's write merge it.
 */

export { MemoryStorage, type KeyValueStorage } from './saved-backups.ts';

/** Free play's key; a teacher's assignment keeps its progress apart under a key of its own. */
export const PROGRESS_KEY = 'rtq.progress';

/** `repaired`: damaged parts were left out, the rest is kept; the others start afresh. */
export type ProgressProblemKind = 'repaired' | 'damaged' | 'foreign' | 'other-version' | 'unreadable-storage';

/** Why saved progress could not be used as it was, and where the old data went. */
export interface ProgressProblem {
  /** What went wrong; the UI words it for the learner, in their language (src/i18n/progress-problem-text.ts). */
  kind: ProgressProblemKind;
  /** The `path: reason` lines (for `repaired`: what was left out), for the curious and for bug reports. */
  reasons: string[];
  /** Where the old text was kept, or null when it could not be (then it is held: see the class comment). */
  backupKey: string | null;
  /** The old text itself, for the UI to offer as a download. */
  raw: string | null;
}

export type LoadedProgress = { progress: Progress; problem?: ProgressProblem };
/**
 * Why a save failed: the storage is full, the browser does not let the app write at all, or
 * damaged saved data that could not be backed up would be written over.
 */
export type SaveProblemKind = 'storage-full' | 'storage-blocked' | 'damaged-held';
/** `saved`: what is in storage now, ours merged with what other tabs had saved. */
export type SaveResult = { ok: true; saved: Progress } | { ok: false; kind: SaveProblemKind };
type ParseProblemKind = 'damaged' | 'foreign' | 'other-version';
export type ProgressParseResult = { ok: true; progress: Progress } | { ok: false; kind: ParseProblemKind; errors: Issue[] };
/** Progress read with its damaged parts left out: `repaired` lists them (empty when nothing was). */
export type ProgressRead = { ok: true; progress: Progress; repaired: string[] } | { ok: false; kind: ParseProblemKind; errors: Issue[] };

export class ProgressStore {
  /** Damaged text still under the progress key because no backup of it could be written. */
  private heldText: string | null = null;

  constructor(
    private readonly storage: KeyValueStorage,
    private readonly clock: QuestClock,
    private readonly key = PROGRESS_KEY,
  ) {}

  load(): LoadedProgress {
    let raw: string | null;
    try {
      raw = this.storage.getItem(this.key);
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      return { progress: newProgress(this.clock), problem: { kind: 'unreadable-storage', reasons: [reason], backupKey: null, raw: null } };
    }
    if (raw === null) return { progress: newProgress(this.clock) };
    const read = readProgressJson(raw, this.nowIso());
    if (read.ok && read.repaired.length === 0) return { progress: read.progress };
    const backupKey = writeBackup(this.storage, this.key, raw, this.clock.wallMs());
    if (backupKey === null) this.heldText = raw;
    const problem: ProgressProblem = read.ok
      ? { kind: 'repaired', reasons: read.repaired, backupKey, raw }
      : { kind: read.kind, reasons: read.errors.map(issueLine), backupKey, raw };
    return { progress: read.ok ? read.progress : newProgress(this.clock), problem };
  }

  /** The saved progress when it can be used (its damaged parts left out), else null (for merging; load() reports problems). */
  read(): Progress | null {
    try {
      const raw = this.storage.getItem(this.key);
      if (raw === null) return null;
      const read = readProgressJson(raw, this.nowIso());
      return read.ok ? read.progress : null;
    } catch {
      return null;
    }
  }

  /**
   * Saves `progress` merged with what is saved (another tab's work), or says why not: the
   * caller keeps the progress in memory either way and saves again later. Damaged saved
   * data is written over only once it is backed up (load() or the retry here) or released.
   */
  save(progress: Progress): SaveResult {
    if (this.heldText !== null) {
      if (writeBackup(this.storage, this.key, this.heldText, this.clock.wallMs()) === null) return { ok: false, kind: 'damaged-held' };
      this.heldText = null;
    }
    const stored = this.read();
    const saved = stored ? mergeProgress(progress, stored) : progress;
    try {
      this.storage.setItem(this.key, JSON.stringify(saved));
      return { ok: true, saved };
    } catch (error) {
      return { ok: false, kind: isQuotaError(error) ? 'storage-full' : 'storage-blocked' };
    }
  }

  /** The damaged text that is held (not yet backed up, not to be written over), or null. */
  get held(): string | null {
    return this.heldText;
  }

  /** The learner has the held text (downloaded): saves may write over it now. */
  release(): void {
    this.heldText = null;
  }

  /**
   * A fresh start that replaces the saved progress once saved (the UI asks first). It is
   * written, not removed: its new epoch tells other tabs to drop the old progress too
   * rather than write it back.
   */
  reset(before: Progress): Progress {
    return replacing(newProgress(this.clock), before, this.clock);
  }

  private nowIso(): string {
    return new Date(this.clock.wallMs()).toISOString();
  }
}

/** Checks progress read from storage or a file: first that it is ours, then its version, then every field. */
export function parseProgress(input: unknown): ProgressParseResult {
  if (!isRecord(input) || input.kind !== PROGRESS_KIND) {
    const got = isRecord(input) ? { inField: true, got: gotOf(input.kind) } : { inField: false, got: gotOf(input) };
    return { ok: false, kind: 'foreign', errors: [{ path: 'kind', reason: { code: 'progressKind', kind: PROGRESS_KIND, ...got } }] };
  }
  if (input.version !== PROGRESS_VERSION) {
    const reason: Reason = { code: 'progressVersion', version: PROGRESS_VERSION, got: gotOf(input.version) };
    return { ok: false, kind: 'other-version', errors: [{ path: 'version', reason }] };
  }
  const result = progressSchema.safeParse(input, { error: describeIssue });
  return result.success ? { ok: true, progress: result.data } : { ok: false, kind: 'damaged', errors: issuesOf(result.error.issues) };
}

/** Progress from the text of storage or of an imported file (the learner's "import progress"). */
export function parseProgressJson(text: string): ProgressParseResult {
  const json = readJson(text);
  return json.ok ? parseProgress(json.value) : { ok: false, kind: 'damaged', errors: [json.issue] };
}

/**
 * Progress from the text of storage, an imported file or a backup, keeping what can be kept:
 * strictly checked first, then, when only some of its parts are damaged, with those left out
 * (`repaired` lists them). Text that is not progress of this version is refused as by parseProgress.
 */
export function readProgressJson(text: string, nowIso: string): ProgressRead {
  const json = readJson(text);
  if (!json.ok) return { ok: false, kind: 'damaged', errors: [json.issue] };
  const strict = parseProgress(json.value);
  if (strict.ok) return { ...strict, repaired: [] };
  const salvaged = strict.kind === 'damaged' && isRecord(json.value) ? salvageProgress(json.value, nowIso) : null;
  return salvaged ? { ok: true, progress: salvaged.progress, repaired: salvaged.notes } : strict;
}

/** `progress` as the one that replaces `before` and all saved earlier (an import, a reset): a new epoch. */
export function replacing(progress: Progress, before: Progress, clock: QuestClock): Progress {
  return { ...progress, epoch: newEpoch(clock.wallMs(), before.epoch) };
}

/** The text of an exported progress file. */
export function exportProgress(progress: Progress): string {
  return `${JSON.stringify(progress, null, 2)}\n`;
}
