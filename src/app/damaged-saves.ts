import { mergeProgress } from '../quest/progress-merge.ts';
import type { Progress } from '../quest/progress.ts';
import type { ProgressStore } from '../quest/progress-store.ts';
import { listBackups, type KeyValueStorage } from '../quest/saved-backups.ts';
import { surveyKey } from '../classroom/survey-store.ts';
import { conceptTestKey } from '../classroom/concept-test/concept-test-store.ts';
import type { PendingWrites } from './pending-writes.ts';
import { sessionContextKey } from './session-context.ts';

/**
 * The Menu's "Damaged saves": every copy of saved data that could not be used as it was,
 * for this session's progress key, its session record, its survey answers and its concept-test
 * answers — the backups in storage, and the
 * damaged text still held under its own key because there was no room for a backup. Each
 * can be downloaded exactly as it was; a backup can be deleted (to free space) and a held
 * one is released once downloaded, so that saving goes on.
 */

/** One damaged save. `held`: still under its own key (no backup), `key` is then that key. */
export interface DamagedSave {
  key: string;
  what: 'progress' | 'session' | 'survey' | 'concept-test';
  /** When the backup was made (ISO 8601), or null for a held one. */
  madeAt: string | null;
  /** Its length in characters. */
  size: number;
  held: boolean;
}

export class DamagedSaves {
  private listed: DamagedSave[] = [];
  /** Each record kept next to the progress, by what it is. */
  private readonly records: ReadonlyMap<string, DamagedSave['what']>;

  constructor(
    private readonly storage: KeyValueStorage,
    private readonly progress: ProgressStore,
    private readonly writes: PendingWrites,
    progressKey: string,
  ) {
    this.records = new Map<string, DamagedSave['what']>([
      [progressKey, 'progress'],
      [sessionContextKey(progressKey), 'session'],
      [surveyKey(progressKey), 'survey'],
      [conceptTestKey(progressKey), 'concept-test'],
    ]);
    this.refresh();
  }

  /** As found at the last refresh (reading every backup's size on each render would be slow). */
  get all(): readonly DamagedSave[] {
    return this.listed;
  }

  /** Looks again: after a save that may have backed up a held text, a release or a deletion. */
  refresh(): void {
    const what = (key: string): DamagedSave['what'] => this.records.get(key) ?? 'progress';
    const held: DamagedSave[] = [...this.records].flatMap(([key, kind]) => {
      const text = kind === 'progress' ? this.progress.held : this.writes.held(key);
      return text === null ? [] : [{ key, what: kind, madeAt: null, size: text.length, held: true }];
    });
    const stored = listBackups(this.storage, [...this.records.keys()]).map(({ key, of, madeAt, size }) => ({
      key,
      what: what(of),
      madeAt,
      size,
      held: false,
    }));
    this.listed = [...held, ...stored];
  }

  /** The exact text of a damaged save, or null when it is gone (deleted in another tab). */
  text(key: string): string | null {
    const entry = this.listed.find((save) => save.key === key);
    if (!entry) return null;
    if (entry.held) return entry.what === 'progress' ? this.progress.held : this.writes.held(key);
    try {
      return this.storage.getItem(key);
    } catch {
      return null;
    }
  }

  /** The learner has downloaded it: a held text may now be written over. */
  downloaded(key: string): void {
    const entry = this.listed.find((save) => save.key === key);
    if (!entry?.held) return;
    if (entry.what === 'progress') this.progress.release();
    else this.writes.release(key);
    this.refresh();
  }

  /** Deletes a backup (not a held text: that is the save itself). */
  delete(key: string): void {
    const entry = this.listed.find((save) => save.key === key);
    if (!entry || entry.held) return;
    try {
      this.storage.removeItem(key);
    } catch {
      // Storage that cannot be written: the backup stays, and the list says so after the refresh.
    }
    this.refresh();
  }

  what(key: string): DamagedSave['what'] | null {
    return this.listed.find((save) => save.key === key)?.what ?? null;
  }
}

/**
 * `current` with a restored backup's progress taken in: every task, badge and event of both
 * (progress-merge.ts, as two tabs' saves), the settings as they are now, the sandbox scene
 * kept, or the backup's when there is none.
 */
export function withRestored(current: Progress, restored: Progress): Progress {
  const merged = mergeProgress(current, { ...restored, epoch: current.epoch });
  return { ...merged, sandbox: current.sandbox ?? restored.sandbox };
}

/** The download's name: what it is and when it was kept ("ray-tracer-quest-damaged-progress-2025-03-01T09-00-00.json"). */
export function damagedSaveFileName(save: DamagedSave): string {
  const what = { progress: 'progress', session: 'session-record', survey: 'survey-answers', 'concept-test': 'concept-test-answers' }[save.what];
  const when = save.madeAt ? `-${save.madeAt.slice(0, 19).replaceAll(':', '-')}` : '';
  return `ray-tracer-quest-damaged-${what}${when}.json`;
}
