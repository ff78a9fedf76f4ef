import { randomBytes } from 'node:crypto';
import { mkdtempSync, mkdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { afterFirstScreen, checkFirstLoad, FIRST_LOAD_BUDGET_BYTES, firstLoad, type Manifest } from '../../scripts/first-load.ts';

/**
 * A built app as vite writes it: an entry that awaits the app (a dynamic import), the app
 * importing a shared chunk, the Dutch catalogue and the patterns loaded with it, the level
 * texts in each language, and the 3D view and the dashboard loaded on demand from the app,
 * sharing a chunk of their own.
 */
function dist(appBytes: number): string {
  const dir = mkdtempSync(join(tmpdir(), 'first-load-'));
  mkdirSync(join(dir, 'assets'));
  mkdirSync(join(dir, '.vite'));
  // Random bytes do not compress: their gzip size is a little over their length.
  const noise = (length: number) => randomBytes(length);
  const files: Record<string, Buffer | string> = {
    'assets/index.js': 'await import("./app.js");',
    'assets/app.js': noise(appBytes),
    'assets/shared.js': 'export const a = 1;'.repeat(100),
    'assets/nl.js': noise(2000),
    'assets/levels-en.js': noise(3000),
    'assets/levels-nl.js': noise(3100),
    'assets/local-reason.js': noise(500),
    'assets/view.js': noise(150_000),
    'assets/three.js': noise(100_000),
    'assets/dashboard.js': noise(40_000),
  };
  for (const [file, content] of Object.entries(files)) writeFileSync(join(dir, file), content);
  const manifest: Manifest = {
    'index.html': { file: 'assets/index.js', isEntry: true, dynamicImports: ['src/app.ts'] },
    'src/app.ts': {
      file: 'assets/app.js',
      imports: ['_shared.js'],
      dynamicImports: ['src/locales/nl.ts', 'src/i18n/local-reason.ts', 'virtual:level-texts/en', 'virtual:level-texts/nl', 'src/view.ts', 'src/dashboard.ts'],
    },
    'virtual:level-texts/en': { file: 'assets/levels-en.js' },
    'virtual:level-texts/nl': { file: 'assets/levels-nl.js' },
    'src/i18n/local-reason.ts': { file: 'assets/local-reason.js', imports: ['_shared.js'] },
    '_shared.js': { file: 'assets/shared.js' },
    'src/locales/nl.ts': { file: 'assets/nl.js', imports: ['_shared.js'] },
    'src/view.ts': { file: 'assets/view.js', imports: ['_three.js', '_shared.js'] },
    'src/dashboard.ts': { file: 'assets/dashboard.js', imports: ['_three.js'] },
    '_three.js': { file: 'assets/three.js' },
  };
  writeFileSync(join(dir, '.vite/manifest.json'), JSON.stringify(manifest));
  return dir;
}

const gzipLength = (text: string) => gzipSync(text, { level: 9 }).length;

describe('the first-load budget', () => {
  it('counts the entry, what it awaits and their static imports, not what loads on demand', () => {
    const load = firstLoad(dist(1000));
    expect(load.files.map((file) => file.file)).toEqual(['assets/index.js', 'assets/app.js', 'assets/shared.js', 'assets/levels-en.js']);
    expect(load.files[2].gzipBytes).toBe(gzipLength('export const a = 1;'.repeat(100)));
    expect(checkFirstLoad(load).ok).toBe(true);
  });

  it('adds the catalogue of a learner in another language and the levels in that language only', () => {
    const dir = dist(1000);
    const dutch = firstLoad(dir, 'nl');
    expect(dutch.files.map((file) => file.file)).toEqual(['assets/index.js', 'assets/app.js', 'assets/shared.js', 'assets/nl.js', 'assets/levels-nl.js']);
    expect(dutch.gzipBytes).toBeGreaterThan(firstLoad(dir).gzipBytes + 2000);
    expect(() => firstLoad(dir, 'fr')).toThrow(/no catalogue for "fr"/);
  });

  it('lists each on-demand part with the chunks only it adds, largest first', () => {
    const parts = afterFirstScreen(dist(1000));
    expect(parts.map((part) => part.source)).toEqual(['src/view.ts', 'src/dashboard.ts', 'src/i18n/local-reason.ts']);
    // The view brings three.js; the shared chunk is in the first load already.
    expect(parts[0].gzipBytes).toBeGreaterThan(250_000);
    expect(parts[1].gzipBytes).toBeGreaterThan(140_000);
    expect(parts[1].gzipBytes).toBeLessThan(parts[0].gzipBytes);
  });

  it('fails when over the budget, saying by how much', () => {
    const check = checkFirstLoad(firstLoad(dist(FIRST_LOAD_BUDGET_BYTES + 10_000)));
    expect(check.ok).toBe(false);
    expect(check.lines.at(-1)).toMatch(/^First load \(en\): .* budget 250\.0 kB: OVER by \d+\.\d kB\.$/);
  });
});
