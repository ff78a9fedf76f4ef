import { randomBytes } from 'node:crypto';
import { mkdtempSync, mkdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { checkFirstLoad, FIRST_LOAD_BUDGET_BYTES, firstLoad } from '../../scripts/first-load.ts';

/** A built app: an entry, a preloaded chunk, and a page loaded on demand that must not count. */
function dist(entryBytes: number): string {
  const dir = mkdtempSync(join(tmpdir(), 'first-load-'));
  mkdirSync(join(dir, 'assets'));
  // Random bytes do not compress: their gzip size is a little over their length.
  const noise = (length: number) => randomBytes(length);
  writeFileSync(join(dir, 'assets/index.js'), noise(entryBytes));
  writeFileSync(join(dir, 'assets/shared.js'), 'export const a = 1;'.repeat(100));
  writeFileSync(join(dir, 'assets/dashboard.js'), noise(400_000));
  writeFileSync(
    join(dir, 'index.html'),
    '<html><head><script type="module" crossorigin src="./assets/index.js"></script><link rel="modulepreload" crossorigin href="./assets/shared.js"></head></html>',
  );
  return dir;
}

describe('the first-load budget', () => {
  it('counts the entry and its preloaded chunks, not the pages loaded later', () => {
    const load = firstLoad(dist(1000));
    expect(load.files.map((file) => file.file)).toEqual(['assets/index.js', 'assets/shared.js']);
    expect(load.files[1].gzipBytes).toBe(gzipSync('export const a = 1;'.repeat(100), { level: 9 }).length);
    expect(checkFirstLoad(load).ok).toBe(true);
  });

  it('fails when over the budget, saying by how much', () => {
    const check = checkFirstLoad(firstLoad(dist(FIRST_LOAD_BUDGET_BYTES + 10_000)));
    expect(check.ok).toBe(false);
    expect(check.lines.at(-1)).toMatch(/budget 250\.0 kB: OVER by \d+\.\d kB\.$/);
  });
});
