import { describe, expect, it } from 'vitest';
import { exportInstallId, INSTALL_ID_KEY, isUuid, learnerId } from '../../src/classroom/learner-identity.ts';
import { MemoryStorage } from '../../src/quest/progress-store.ts';

describe('install id in exports', () => {
  it('is neither made, kept nor exported when the learner has a participant code', () => {
    const storage = new MemoryStorage();
    expect(exportInstallId('5H2-03', storage)).toBe('');
    expect(storage.getItem(INSTALL_ID_KEY)).toBeNull();
    expect(learnerId('5H2-03', '')).toBe('5H2-03');
  });

  it('names a learner without a code by this browser, the same id every time', () => {
    const storage = new MemoryStorage();
    const id = exportInstallId(null, storage);
    expect(isUuid(id)).toBe(true);
    expect(exportInstallId(null, storage)).toBe(id);
    expect(learnerId(null, id)).toBe(`install:${id}`);
  });
});
