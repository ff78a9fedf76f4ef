import type { KeyValueStorage } from '../../src/quest/saved-backups.ts';

/**
 * A Storage as browsers keep it: every key and value counts against a quota (in UTF-16 code
 * units, as Chromium counts localStorage), and a write that would go over it throws a
 * QuotaExceededError DOMException and changes nothing, also when it would replace a value.
 * Not a stub: it fails only when the data does not fit, so a test shows both what fails
 * and what succeeds once there is room.
 */
export class QuotaStorage implements KeyValueStorage {
  private readonly items = new Map<string, string>();

  constructor(public quota: number) {}

  get length(): number {
    return this.items.size;
  }

  key(index: number): string | null {
    return [...this.items.keys()][index] ?? null;
  }

  getItem(key: string): string | null {
    return this.items.get(key) ?? null;
  }

  setItem(key: string, value: string): void {
    const old = this.items.get(key);
    const after = this.used - (old === undefined ? 0 : key.length + old.length) + key.length + value.length;
    if (after > this.quota) throw new DOMException(`Setting the value of '${key}' exceeded the quota.`, 'QuotaExceededError');
    this.items.set(key, value);
  }

  removeItem(key: string): void {
    this.items.delete(key);
  }

  /** Code units stored. */
  get used(): number {
    let used = 0;
    for (const [key, value] of this.items) used += key.length + value.length;
    return used;
  }

  /** Fills the storage with other data of the app's origin (key `filler`) until only `free` code units are left. */
  fill(free: number): void {
    this.removeItem('filler');
    this.setItem('filler', 'x'.repeat(Math.max(0, this.quota - this.used - free - 'filler'.length)));
  }
}
