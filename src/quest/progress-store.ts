import { describeIssue, describeValue, formatIssues } from '../scene/scene-issues.ts';
import type { QuestClock } from './event-log.ts';
import { isRecord } from '../util/is-record.ts';
import { newEpoch, newProgress, PROGRESS_KIND, PROGRESS_VERSION, progressSchema, type Progress } from './progress.ts';
import { mergeProgress } from './progress-merge.ts';
import { readJson } from '../util/read-json.ts';

/**
 * Saves progress between visits (localStorage in the browser) and reads it back. Saved data
 * that cannot be used (damaged, from another app, from another version) never ends in a
 * blank screen: the learner starts afresh with a message, and the old text is kept under a
 * backup key (and handed to the UI, to offer it as a download).
 *
 * Several tabs share one saved progress: a save merges with what is saved (progress-merge.ts)
 * instead of writing over it, and `read()` lets a tab that heard of another's write merge it.
 */

/** What the store needs of localStorage, so that tests and blocked browsers can use a Map. */
export interface KeyValueStorage {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
  removeItem(key: string): void;
}

/** A storage that lives as long as the page: for tests, and for browsers that block localStorage. */
export class MemoryStorage implements KeyValueStorage {
  private readonly items = new Map<string, string>();

  getItem(key: string): string | null {
    return this.items.get(key) ?? null;
  }

  setItem(key: string, value: string): void {
    this.items.set(key, value);
  }

  removeItem(key: string): void {
    this.items.delete(key);
  }
}

/** Free play's key; a teacher's assignment keeps its progress apart under a key of its own. */
export const PROGRESS_KEY = 'rtq.progress';

export type ProgressProblemKind = 'damaged' | 'foreign' | 'other-version' | 'unreadable-storage';

/** Why saved progress could not be used, and where the old data went. */
export interface ProgressProblem {
  /** What went wrong; the UI words it for the learner, in their language (src/i18n/progress-problem-text.ts). */
  kind: ProgressProblemKind;
  /** The `path: reason` lines, for the curious and for bug reports. */
  reasons: string[];
  /** Where the old text was kept, or null when it could not be kept. */
  backupKey: string | null;
  /** The old text itself, for the UI to offer as a download. */
  raw: string | null;
}

export type LoadedProgress = { progress: Progress; problem?: ProgressProblem };
/** Why a save failed: the storage is full, or the browser does not let the app write at all. */
export type SaveProblemKind = 'storage-full' | 'storage-blocked';
/** `saved`: what is in storage now, ours merged with what other tabs had saved. */
export type SaveResult = { ok: true; saved: Progress } | { ok: false; kind: SaveProblemKind };
type ParseProblemKind = Exclude<ProgressProblemKind, 'unreadable-storage'>;
export type ProgressParseResult = { ok: true; progress: Progress } | { ok: false; kind: ParseProblemKind; errors: string[] };

export class ProgressStore {
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
      return this.fresh({ kind: 'unreadable-storage', reasons: [reason], backupKey: null, raw: null });
    }
    if (raw === null) return { progress: newProgress(this.clock) };
    const parsed = parseProgressJson(raw);
    if (parsed.ok) return { progress: parsed.progress };
    const backupKey = this.backUp(raw);
    return this.fresh({ kind: parsed.kind, reasons: parsed.errors, backupKey, raw });
  }

  /** The saved progress when it can be used, else null (for merging; load() reports problems). */
  read(): Progress | null {
    try {
      const raw = this.storage.getItem(this.key);
      if (raw === null) return null;
      const parsed = parseProgressJson(raw);
      return parsed.ok ? parsed.progress : null;
    } catch {
      return null;
    }
  }

  /**
   * Saves `progress` merged with what is saved (another tab's work), or says why not: the
   * caller keeps the progress in memory either way. Saved data that cannot be read was
   * backed up by load() and is written over.
   */
  save(progress: Progress): SaveResult {
    const stored = this.read();
    const saved = stored ? mergeProgress(progress, stored) : progress;
    try {
      this.storage.setItem(this.key, JSON.stringify(saved));
      return { ok: true, saved };
    } catch (error) {
      const full = error instanceof Error && (error.name === 'QuotaExceededError' || error.name === 'NS_ERROR_DOM_QUOTA_REACHED');
      return { ok: false, kind: full ? 'storage-full' : 'storage-blocked' };
    }
  }

  /**
   * A fresh start that replaces the saved progress once saved (the UI asks first). It is
   * written, not removed: its new epoch tells other tabs to drop the old progress too
   * rather than write it back.
   */
  reset(before: Progress): Progress {
    return replacing(newProgress(this.clock), before, this.clock);
  }

  private fresh(problem: ProgressProblem): LoadedProgress {
    return { progress: newProgress(this.clock), problem };
  }

  /** Keeps `raw` under a key of its own (never over an older backup); null when storage refuses. */
  private backUp(raw: string): string | null {
    const backupKey = `${this.key}.backup.${new Date(this.clock.wallMs()).toISOString()}`;
    try {
      if (this.storage.getItem(backupKey) !== null) return null;
      this.storage.setItem(backupKey, raw);
      return backupKey;
    } catch {
      return null;
    }
  }
}

/** Checks progress read from storage or a file: first that it is ours, then its version, then every field. */
export function parseProgress(input: unknown): ProgressParseResult {
  if (!isRecord(input) || input.kind !== PROGRESS_KIND) {
    const got = isRecord(input) ? `"kind" ${describeValue(input.kind)}` : describeValue(input);
    return { ok: false, kind: 'foreign', errors: [`kind: must be "${PROGRESS_KIND}" in a progress file, got ${got}`] };
  }
  if (input.version !== PROGRESS_VERSION) {
    return { ok: false, kind: 'other-version', errors: [`version: this app reads progress version ${PROGRESS_VERSION}, got ${describeValue(input.version)}`] };
  }
  const result = progressSchema.safeParse(input, { error: describeIssue });
  return result.success ? { ok: true, progress: result.data } : { ok: false, kind: 'damaged', errors: formatIssues(result.error.issues) };
}

/** Progress from the text of storage or of an imported file (the learner's "import progress"). */
export function parseProgressJson(text: string): ProgressParseResult {
  const json = readJson(text);
  return json.ok ? parseProgress(json.value) : { ok: false, kind: 'damaged', errors: [json.error] };
}

/** `progress` as the one that replaces `before` and all saved earlier (an import, a reset): a new epoch. */
export function replacing(progress: Progress, before: Progress, clock: QuestClock): Progress {
  return { ...progress, epoch: newEpoch(clock.wallMs(), before.epoch) };
}

/** The text of an exported progress file. */
export function exportProgress(progress: Progress): string {
  return `${JSON.stringify(progress, null, 2)}\n`;
}
