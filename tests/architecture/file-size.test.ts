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
