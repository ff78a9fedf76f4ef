import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { initialState } from '../../src/lab-state/lab-state.ts';
import { QuestSession } from '../../src/app/quest-session.ts';
import { Store } from '../../src/lab-state/store.ts';
import { labCodeImportText } from '../../src/i18n/lab-code-import-text.ts';
import { LAB_CODE_MAX } from '../../src/quest/progress-lab-code.ts';
import { MemoryStorage, PROGRESS_KEY } from '../../src/quest/progress-store.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { catalogOf, FakeClock, levelWithId } from '../support/quest-fixtures.ts';

const catalog = catalogOf([{ id: 'test', levels: [levelWithId('first'), levelWithId('second')] }]);
const SPHERE = 'rtq.code-lab.ray-sphere';
const MIRROR = 'rtq.code-lab.mirror';

function session(storage = new MemoryStorage()) {
  const store = new Store(initialState(defaultScene()));
  const game = new QuestSession({ store, catalog, storage, assignment: null, clock: new FakeClock() });
  game.start();
  return game;
}

/** A storage that takes everything but the code labs' keys, as a full one would refuse a long text. */
class CodeRefusingStorage extends MemoryStorage {
  override setItem(key: string, value: string): void {
    if (key.startsWith('rtq.code-lab.')) throw new DOMException('full', 'QuotaExceededError');
    super.setItem(key, value);
  }
}

/** A progress file from another browser: the palette changed (to see the import happened) and the given `code`. */
function fileWith(code: unknown): string {
  const file = JSON.parse(session().exportText());
  file.settings.colorBlindPalette = true;
  if (code !== undefined) file.code = code;
  return JSON.stringify(file);
}

const palette = (storage: MemoryStorage) => JSON.parse(storage.getItem(PROGRESS_KEY) ?? 'null').settings.colorBlindPalette;

describe('the learner’s code in the progress file', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('is exported per lab and comes back on import in another browser, not into the saved progress', () => {
    const here = new MemoryStorage();
    here.setItem(SPHERE, 'function hitSphere() { return 1; }');
    here.setItem(MIRROR, 'function reflect() {}');
    const file = session(here).exportText();
    expect(JSON.parse(file).code).toEqual({ 'ray-sphere': 'function hitSphere() { return 1; }', mirror: 'function reflect() {}' });

    const there = new MemoryStorage();
    expect(session(there).importText(file)).toEqual({ ok: true, repaired: [] });
    expect(there.getItem(SPHERE)).toBe('function hitSphere() { return 1; }');
    expect(there.getItem(MIRROR)).toBe('function reflect() {}');
    expect(JSON.parse(there.getItem(PROGRESS_KEY) ?? 'null')).not.toHaveProperty('code');
  });

  it('leaves the field out of a file when there is no code', () => {
    expect(JSON.parse(session().exportText())).not.toHaveProperty('code');
  });

  it('reads a file from before code was exported, and keeps the code this browser has', () => {
    const storage = new MemoryStorage();
    storage.setItem(SPHERE, 'mine');
    expect(session(storage).importText(fileWith(undefined))).toEqual({ ok: true, repaired: [] });
    expect(palette(storage)).toBe(true);
    expect(storage.getItem(SPHERE)).toBe('mine');
  });

  it('refuses a lab’s code that is not text or too long, and imports the rest of the file', () => {
    const storage = new MemoryStorage();
    storage.setItem(SPHERE, 'kept sphere');
    storage.setItem(MIRROR, 'kept mirror');
    const code = { 'ray-sphere': 'x'.repeat(LAB_CODE_MAX + 1), mirror: 42, refraction: 'function refract() {}' };
    const result = session(storage).importText(fileWith(code));
    expect(result).toEqual({ ok: true, repaired: [], code: { refused: ['ray-sphere', 'mirror'], notSaved: [] } });
    expect(storage.getItem(SPHERE)).toBe('kept sphere');
    expect(storage.getItem(MIRROR)).toBe('kept mirror');
    expect(storage.getItem('rtq.code-lab.refraction')).toBe('function refract() {}');
    expect(palette(storage)).toBe(true);
  });

  it('takes code of exactly the most characters', () => {
    const storage = new MemoryStorage();
    const longest = 'y'.repeat(LAB_CODE_MAX);
    expect(session(storage).importText(fileWith({ 'ray-sphere': longest }))).toEqual({ ok: true, repaired: [] });
    expect(storage.getItem(SPHERE)).toBe(longest);
  });

  it('refuses a `code` that is not a record whole, and imports the rest', () => {
    const storage = new MemoryStorage();
    storage.setItem(SPHERE, 'kept');
    expect(session(storage).importText(fileWith('not code'))).toEqual({ ok: true, repaired: [], code: { refused: [''], notSaved: [] } });
    expect(storage.getItem(SPHERE)).toBe('kept');
    expect(palette(storage)).toBe(true);
  });

  it('says which labs’ code storage did not take, the progress imported all the same', () => {
    const storage = new CodeRefusingStorage();
    const result = session(storage).importText(fileWith({ 'ray-sphere': 'function hitSphere() {}' }));
    expect(result).toEqual({ ok: true, repaired: [], code: { refused: [], notSaved: ['ray-sphere'] } });
    expect(palette(storage)).toBe(true);
  });

  it('tells the learner what was refused and why, and that their code here is kept', () => {
    expect(labCodeImportText(undefined)).toBe('');
    const refused = labCodeImportText({ refused: ['ray-sphere', 'mirror'], notSaved: [] });
    expect(refused).toContain('Your code for “ray-sphere”, “mirror” was not imported');
    expect(refused).toMatch(/must be text of at most 20.000 characters\. The code this browser had for it is kept\./);
    expect(labCodeImportText({ refused: [''], notSaved: [] })).toContain('Your code for every lab was not imported');
    expect(labCodeImportText({ refused: [], notSaved: ['mirror'] })).toContain('“mirror” could not be saved in this browser');
  });
});
