import type { SaveProblemKind } from '../quest/progress-store.ts';
import { isQuotaError, writeBackup, type KeyValueStorage } from '../quest/saved-backups.ts';

/**
 * The small records a session writes next to the progress (the participant code and attempt,
 * the survey answers), or removes (a damaged record of which nothing could be read). A write the storage refuses is not forgotten: the text stays here
 * and is written at the next save (the session saves on every change and when the page is
 * left), so the records are never lost while the page is open and never said to be saved
 * when they are not.
 *
 * A key can be held: its stored text is damaged and has no backup yet, so it is not written
 * over until a backup of it succeeds (tried at every flush) or the learner has downloaded it.
 */
export class PendingWrites {
  /** null: the key is to be removed (a damaged record with nothing readable, once backed up). */
  private readonly texts = new Map<string, string | null>();
  private readonly heldTexts = new Map<string, string>();

  constructor(
    private readonly storage: KeyValueStorage,
    private readonly wallMs: () => number,
  ) {}

  /** Writes `text` under `key` at the next flush (replacing a text still waiting there); null removes the key. */
  put(key: string, text: string | null): void {
    this.texts.set(key, text);
  }

  /** Whether `key` still waits to be written. */
  waiting(key: string): boolean {
    return this.texts.has(key);
  }

  get anyWaiting(): boolean {
    return this.texts.size > 0;
  }

  /** `raw`, stored under `key`, is damaged and not backed up: nothing is written over it yet. */
  hold(key: string, raw: string): void {
    this.heldTexts.set(key, raw);
  }

  /**
   * A record found damaged when the session started: held while it has no backup (nothing is
   * written over it until it has, or the learner has downloaded it), and what could be read of
   * it (`readable`; null: nothing) written in its place at the next flush, after the backup, so
   * that the next visit does not find the damage again and back it up once more.
   */
  replaceDamaged(key: string, damage: { raw: string; backupKey: string | null }, readable: string | null): void {
    if (damage.backupKey === null) this.hold(key, damage.raw);
    this.put(key, readable);
  }

  held(key: string): string | null {
    return this.heldTexts.get(key) ?? null;
  }

  /** The learner has the held text: `key` may be written again. */
  release(key: string): void {
    this.heldTexts.delete(key);
  }

  /** Writes what waits; the first reason a write failed, or null when all are written. */
  flush(): SaveProblemKind | null {
    let problem: SaveProblemKind | null = null;
    for (const [key, text] of [...this.texts]) {
      const held = this.heldTexts.get(key);
      if (held !== undefined) {
        if (writeBackup(this.storage, key, held, this.wallMs()) === null) {
          problem ??= 'damaged-held';
          continue;
        }
        this.heldTexts.delete(key);
      }
      try {
        if (text === null) this.storage.removeItem(key);
        else this.storage.setItem(key, text);
        this.texts.delete(key);
      } catch (error) {
        problem ??= isQuotaError(error) ? 'storage-full' : 'storage-blocked';
      }
    }
    return problem;
  }
}
