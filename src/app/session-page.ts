import type { QuestEngine } from '../quest/quest-engine.ts';
import type { KeyValueStorage } from '../quest/saved-backups.ts';
import type { SessionMode } from './quest-session.ts';

/** What the page's events need of the quest session. */
export interface PageSession {
  readonly engine: QuestEngine;
  readonly mode: SessionMode;
  subscribe(listener: () => void): () => void;
  /** Saves what waits (quest-session.ts). */
  flush(): void;
  /** Another tab wrote `key` of the storage. */
  storageChanged(key: string | null): void;
}

/**
 * Ties a quest session to the page: follows the tab's visibility (hidden time is not idle
 * time) and ticks the engine once a second, only while a level is open and the tab is seen,
 * so a hint can be offered after idle time; listens for other tabs' saves (`storage` events
 * of the session's storage); and saves what waits when the page is left. Returns the undo.
 */
export function attachToPage(session: PageSession, document: Document, storage: KeyValueStorage): () => void {
  let timer: ReturnType<typeof setInterval> | undefined;
  const update = () => {
    const visible = document.visibilityState === 'visible';
    session.engine.visibilityChanged(visible);
    const ticking = visible && session.mode.kind === 'level';
    if (ticking && timer === undefined) timer = setInterval(() => session.engine.tick(), 1000);
    if (!ticking && timer !== undefined) {
      clearInterval(timer);
      timer = undefined;
    }
  };
  const unsubscribe = session.subscribe(update);
  // Leaving the page (closing the tab, a reload, switching apps on a phone) saves what waits:
  // 'pagehide' is the last event a closing page is sure to get, 'hidden' the last a phone
  // sends before it may discard the page without one.
  const onVisibility = () => {
    if (document.visibilityState === 'hidden') session.flush();
    update();
  };
  const onLeave = () => session.flush();
  const onStorage = (event: StorageEvent) => {
    if (event.storageArea === storage) session.storageChanged(event.key);
  };
  const window = document.defaultView;
  document.addEventListener('visibilitychange', onVisibility);
  window?.addEventListener('storage', onStorage);
  window?.addEventListener('pagehide', onLeave);
  update();
  return () => {
    unsubscribe();
    document.removeEventListener('visibilitychange', onVisibility);
    window?.removeEventListener('storage', onStorage);
    window?.removeEventListener('pagehide', onLeave);
    clearInterval(timer);
  };
}
