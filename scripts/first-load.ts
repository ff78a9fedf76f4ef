import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

/**
 * What a student's browser downloads as JavaScript before the game can start: the module
 * scripts `index.html` names and the chunks it preloads (vite writes a modulepreload link
 * for every chunk the entry imports statically). Pages loaded on demand (the teacher page,
 * the dashboard) and the render worker are listed apart: they are not in the first load.
 * Sizes are gzip level 9, as a static host serves them.
 */

/** The budget of spec issue 11: a school laptop on a busy classroom network. */
export const FIRST_LOAD_BUDGET_BYTES = 250 * 1024;

export interface FirstLoad {
  files: { file: string; gzipBytes: number }[];
  gzipBytes: number;
}

export function firstLoad(dist: string): FirstLoad {
  const html = readFileSync(join(dist, 'index.html'), 'utf8');
  const sources = [
    ...html.matchAll(/<script[^>]*type="module"[^>]*src="([^"]+)"/g),
    ...html.matchAll(/<link[^>]*rel="modulepreload"[^>]*href="([^"]+)"/g),
  ].map((match) => match[1].replace(/^\.\//, ''));
  const files = [...new Set(sources)].map((file) => ({ file, gzipBytes: gzipSync(readFileSync(join(dist, file)), { level: 9 }).length }));
  return { files, gzipBytes: files.reduce((total, file) => total + file.gzipBytes, 0) };
}

/** The report's lines and whether the load is within `budget`. */
export function checkFirstLoad(load: FirstLoad, budget = FIRST_LOAD_BUDGET_BYTES): { ok: boolean; lines: string[] } {
  const kB = (bytes: number) => `${(bytes / 1024).toFixed(1)} kB`;
  const ok = load.gzipBytes <= budget;
  return {
    ok,
    lines: [
      ...load.files.map((file) => `  ${kB(file.gzipBytes).padStart(10)}  ${file.file}`),
      `First load: ${kB(load.gzipBytes)} of JavaScript (gzip), budget ${kB(budget)}: ${ok ? 'within' : `OVER by ${kB(load.gzipBytes - budget)}`}.`,
    ],
  };
}
