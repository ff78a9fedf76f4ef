import { expect, test } from 'vitest';
import { offlineCopyText } from '../../../src/ui/controls/offline-copy-text.ts';

test('the Menu says the app works offline only once it is stored', () => {
  expect(offlineCopyText({ kind: 'stored', newVersionWaiting: false })).toBe('This app works offline: this browser keeps a copy of it.');
  expect(offlineCopyText({ kind: 'storing' })).not.toMatch(/works offline/);
  expect(offlineCopyText({ kind: 'stored', newVersionWaiting: true })).toMatch(
    /^This app works offline: .* A new version has been stored as well; it starts once every tab of this app has been closed\.$/,
  );
});

test('when the copy cannot be stored, the Menu says so and why', () => {
  const failed = offlineCopyText({ kind: 'not-stored', reason: 'failed', detail: '' });
  expect(failed).toMatch(/^This app is not stored for offline use: .*storage space/);
  expect(failed).not.toMatch(/works offline/);
  expect(offlineCopyText({ kind: 'not-stored', reason: 'unsupported', detail: '' })).toMatch(
    /^This app is not stored for offline use: this browser cannot keep it here/,
  );
  expect(offlineCopyText({ kind: 'not-stored', reason: 'refused', detail: 'SecurityError: insecure origin' })).toBe(
    'This app is not stored for offline use: the browser refused (SecurityError: insecure origin). It works while you are online.',
  );
  expect(offlineCopyText({ kind: 'not-stored', reason: 'refused', detail: '' })).toBe(
    'This app is not stored for offline use: the browser refused. It works while you are online.',
  );
});
