import { msg, str } from '@lit/localize';
import type { OfflineCopyState } from '../../app/offline-copy.ts';

/**
 * What the Menu says about the offline copy (src/app/offline-copy.ts): whether the app opens
 * without a network, and when it does not, why and what still works. Only what is known:
 * "works offline" once the service worker has stored every file, never before.
 */
export function offlineCopyText(state: OfflineCopyState): string {
  switch (state.kind) {
    case 'storing':
      return msg('Storing the app in this browser for offline use…');
    case 'stored':
      return state.newVersionWaiting
        ? msg(
            'This app works offline: this browser keeps a copy of it. A new version has been stored as well; it starts once every tab of this app has been closed.',
          )
        : msg('This app works offline: this browser keeps a copy of it.');
    case 'single-file':
      return msg('This copy of the app is a single file: it works without a network.');
    case 'not-stored':
      switch (state.reason) {
        case 'unsupported':
          return msg(
            'This app is not stored for offline use: this browser cannot keep it here (in a private window, for example). It works while you are online.',
          );
        case 'refused':
          return state.detail
            ? msg(str`This app is not stored for offline use: the browser refused (${state.detail}). It works while you are online.`)
            : msg('This app is not stored for offline use: the browser refused. It works while you are online.');
        case 'failed':
          return msg(
            'This app is not stored for offline use: the browser could not store its files, most likely for lack of storage space. It works while you are online; free some disk space and reload to try again.',
          );
      }
  }
}
