import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

/** An element file that grows past this holds more than one concept: split it (styles, controllers, templates). */
const MAX_UI_FILE_LINES = 400;

const UI = fileURLToPath(new URL('../../src/ui', import.meta.url));

function files(folder: string): string[] {
  return readdirSync(folder).flatMap((name) => {
    const path = join(folder, name);
    return statSync(path).isDirectory() ? files(path) : name.endsWith('.ts') ? [path] : [];
  });
}

describe('src/ui stays in small files', () => {
  it(`has no file over ${MAX_UI_FILE_LINES} lines`, () => {
    const all = files(UI);
    expect(all.length).toBeGreaterThan(50);
    const long = all.map((path) => ({ path, lines: readFileSync(path, 'utf8').split('\n').length })).filter((file) => file.lines > MAX_UI_FILE_LINES);
    expect(long).toEqual([]);
  });
});

/** Outside src/ui a file may hold a little more: one module of logic with its comments. */
const MAX_FILE_LINES = 500;

/**
 * Files over the limit, each with why it is still one piece.
 * A file that shrinks below the limit must leave this list (the test says so).
 */
const ALLOWED_LONG_FILES: Record<string, string> = {
  'render/render-pool.ts':
    "the worker pool: scheduling, the watchdog, recovery and path mode's running sums read and change one job state, whose cancellation contract its tests pin",
};

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const SRC = join(ROOT, 'src');
/** Every folder of code: the app, its workers, the tests of both kinds, the benchmark and the scripts. */
const CODE_FOLDERS = ['src', 'workers', 'tests', 'e2e', 'bench', 'scripts'];

describe('every folder stays in files of one concept', () => {
  const lengths = CODE_FOLDERS.flatMap((folder) => files(join(ROOT, folder)))
    .filter((path) => !path.startsWith(UI) && !path.includes(`${join('src', 'locales')}`))
    .map((path) => ({
      file: path
        .slice(path.startsWith(SRC) ? SRC.length + 1 : ROOT.length)
        .split('\\')
        .join('/'),
      lines: readFileSync(path, 'utf8').split('\n').length,
    }));

  it(`has no file over ${MAX_FILE_LINES} lines but the named ones`, () => {
    expect(lengths.filter(({ file, lines }) => lines > MAX_FILE_LINES && !(file in ALLOWED_LONG_FILES))).toEqual([]);
  });

  it('names no file in the allow-list that is short now', () => {
    const short = Object.keys(ALLOWED_LONG_FILES).filter((file) => (lengths.find((entry) => entry.file === file)?.lines ?? 0) <= MAX_FILE_LINES);
    expect(short).toEqual([]);
  });
});
