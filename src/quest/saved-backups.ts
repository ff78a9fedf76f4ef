/**
 * Copies of saved data that could not be used as it was (damaged, from another version),
 * kept in the same storage under `<key>.backup.<ISO time>` so that the learner can download
 * or restore them from the Menu, and delete them once downloaded to free space.
 */

/** What the stores need of localStorage, so that tests and blocked browsers can use a Map. */
export interface KeyValueStorage {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
  removeItem(key: string): void;
  /** How many keys there are, and the `index`th: to find the backups. */
  readonly length: number;
  key(index: number): string | null;
}

/** Whether a storage error means "no room" (the names browsers give it) rather than "not allowed". */
export function isQuotaError(error: unknown): boolean {
  return error instanceof Error && (error.name === 'QuotaExceededError' || error.name === 'NS_ERROR_DOM_QUOTA_REACHED');
}

const BACKUP = '.backup.';

export function backupKeyOf(key: string, wallMs: number): string {
  return `${key}${BACKUP}${new Date(wallMs).toISOString()}`;
}

/** Keeps `raw` under a backup key of `key` (never over an older backup); the key, or null when storage refuses. */
export function writeBackup(storage: KeyValueStorage, key: string, raw: string, wallMs: number): string | null {
  const backupKey = backupKeyOf(key, wallMs);
  try {
    if (storage.getItem(backupKey) !== null) return null;
    storage.setItem(backupKey, raw);
    return backupKey;
  } catch {
    return null;
  }
}

/** A backup in storage: its key, when it was made, and its size in characters. */
export interface StoredBackup {
  key: string;
  /** The key whose data it copies. */
  of: string;
  madeAt: string;
  size: number;
}

/** The backups of any of `keys`, oldest first; none when storage cannot be read. */
export function listBackups(storage: KeyValueStorage, keys: readonly string[]): StoredBackup[] {
  const found: StoredBackup[] = [];
  try {
    for (let index = 0; index < storage.length; index++) {
      const key = storage.key(index);
      const of = keys.find((candidate) => key?.startsWith(candidate + BACKUP));
      if (key === null || of === undefined) continue;
      found.push({ key, of, madeAt: key.slice(of.length + BACKUP.length), size: storage.getItem(key)?.length ?? 0 });
    }
  } catch {
    return [];
  }
  return found.sort((a, b) => (a.madeAt < b.madeAt ? -1 : a.madeAt > b.madeAt ? 1 : 0));
}

/** A storage that lives as long as the page: for tests, and for browsers that block localStorage. */
export class MemoryStorage implements KeyValueStorage {
  private readonly items = new Map<string, string>();

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
    this.items.set(key, value);
  }

  removeItem(key: string): void {
    this.items.delete(key);
  }
}

/**
 * The storage of a browser that blocks localStorage: nothing is stored and every write is
 * refused as the browser would refuse it, so that no save is said to have happened.
 */
export function refusingStorage(): KeyValueStorage {
  return {
    length: 0,
    key: () => null,
    getItem: () => null,
    setItem: () => {
      throw new DOMException('The browser does not let this page store data.', 'SecurityError');
    },
    removeItem: () => {},
  };
}
