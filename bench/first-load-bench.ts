/**
 * A student's first load of JavaScript (scripts/first-load.ts says what counts), measured on
 * a fresh production build of the app, in English and in Dutch.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { FIRST_LOAD_BUDGET_BYTES, afterFirstScreen, firstLoad, readManifest } from '../scripts/first-load.ts';

const ROOT = fileURLToPath(new URL('..', import.meta.url));

export interface FirstLoadFigures {
  /** Gzipped kB before the first screen, per language. */
  kB: { en: number; nl: number };
  budgetKB: number;
  /** Gzipped kB of the 3D view (three.js and the lab's drawing), loaded once the first screen is up. */
  viewKB: number;
}

export function measureFirstLoad(): FirstLoadFigures {
  const dist = mkdtempSync(join(tmpdir(), 'rt-first-load-'));
  try {
    execFileSync('npx', ['vite', 'build', '--outDir', dist, '--emptyOutDir', '--logLevel', 'error'], { cwd: ROOT, stdio: 'ignore' });
    const manifest = readManifest(dist);
    const kB = (bytes: number) => Math.round(bytes / 102.4) / 10;
    const view = afterFirstScreen(dist, manifest).find((part) => part.source === 'src/view/lab-view.ts');
    return {
      kB: { en: kB(firstLoad(dist, 'en', manifest).gzipBytes), nl: kB(firstLoad(dist, 'nl', manifest).gzipBytes) },
      budgetKB: kB(FIRST_LOAD_BUDGET_BYTES),
      viewKB: kB(view?.gzipBytes ?? 0),
    };
  } finally {
    rmSync(dist, { recursive: true, force: true });
  }
}

export function firstLoadRows(figures: FirstLoadFigures): [string, string, string][] {
  return [
    ['first load, JavaScript gzip: English / Dutch', `${figures.kB.en} / ${figures.kB.nl} kB`, `≤ ${figures.budgetKB} kB`],
    ['3D view, loaded after the first screen', `${figures.viewKB} kB`, ''],
  ];
}
