import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

/**
 * What a student's browser downloads as JavaScript before the game's first screen (the
 * lab's panels, the level's tasks, the level map) can be used, read from vite's build
 * manifest (`dist/.vite/manifest.json`):
 *
 * - the entry script and every chunk it imports statically;
 * - the entry's dynamic imports with their static imports: `src/main.ts` awaits each of them
 *   before the first render (the language, then the app);
 * - for a learner in another language, that language's catalogue of the first screen's
 *   messages (`src/locales/<code>.ts`; the later parts' messages load once the screen is up:
 *   scripts/split-dutch-catalogue.ts);
 * - the level files in the learner's language (`virtual:level-texts/<code>`).
 *
 * What loads once that screen is up is listed apart ("after the first screen"): the 3D view
 * (three.js), the BVH panel, the teacher's pages. The render worker is a file of its own,
 * fetched when the first rays are traced. Sizes are gzip level 9, as a static host serves them.
 */

/** The budget of spec issue 11: a school laptop on a busy classroom network. */
export const FIRST_LOAD_BUDGET_BYTES = 250 * 1024;

/** The module of the level files in one language, by its language code. */
const LEVEL_TEXTS = 'virtual:level-texts/';

/** One chunk of vite's build manifest (the fields used here). */
export interface ManifestChunk {
  file: string;
  isEntry?: boolean;
  imports?: string[];
  dynamicImports?: string[];
}

export type Manifest = Record<string, ManifestChunk>;

export interface FirstLoad {
  /** The learner's language ('en' needs no catalogue). */
  locale: string;
  files: { file: string; gzipBytes: number }[];
  gzipBytes: number;
}

export function readManifest(dist: string): Manifest {
  return JSON.parse(readFileSync(join(dist, '.vite', 'manifest.json'), 'utf8')) as Manifest;
}

/** The manifest keys of `roots` and every chunk they import statically, in visiting order. */
function staticClosure(manifest: Manifest, roots: string[]): string[] {
  const seen = new Set<string>();
  const visit = (key: string) => {
    if (seen.has(key)) return;
    const chunk = manifest[key];
    if (!chunk) throw new Error(`the build manifest names ${key} but has no entry for it`);
    seen.add(key);
    for (const imported of chunk.imports ?? []) visit(imported);
  };
  roots.forEach(visit);
  return [...seen];
}

/** The manifest keys of the first load in `locale`. */
export function firstLoadKeys(manifest: Manifest, locale = 'en'): string[] {
  const entries = Object.keys(manifest).filter((key) => manifest[key].isEntry && manifest[key].file.endsWith('.js'));
  if (entries.length !== 1) throw new Error(`expected one script entry in the build manifest, found ${entries.length}`);
  const [entry] = entries;
  const catalogue = `src/locales/${locale}.ts`;
  if (locale !== 'en' && !manifest[catalogue]) throw new Error(`the build has no catalogue for "${locale}" (${catalogue})`);
  const withCatalogue = locale === 'en' ? [] : [catalogue];
  // The levels' texts in that language (scripts/level-texts-plugin.ts), awaited before the first screen.
  const levelTexts = `${LEVEL_TEXTS}${locale}`;
  if (!manifest[levelTexts]) throw new Error(`the build has no level texts in "${locale}" (${levelTexts})`);
  return staticClosure(manifest, [entry, ...(manifest[entry].dynamicImports ?? []), ...withCatalogue, levelTexts]);
}

function gzipBytes(dist: string, file: string): number {
  return gzipSync(readFileSync(join(dist, file)), { level: 9 }).length;
}

export function firstLoad(dist: string, locale = 'en', manifest = readManifest(dist)): FirstLoad {
  const files = firstLoadKeys(manifest, locale).map((key) => ({ file: manifest[key].file, gzipBytes: gzipBytes(dist, manifest[key].file) }));
  return { locale, files, gzipBytes: files.reduce((total, file) => total + file.gzipBytes, 0) };
}

/** What loads on demand once the first screen is up: each dynamic entry outside the first load, with the chunks only it adds. */
export function afterFirstScreen(dist: string, manifest = readManifest(dist)): { source: string; gzipBytes: number }[] {
  const first = new Set(firstLoadKeys(manifest));
  const dynamicEntries = new Set(Object.values(manifest).flatMap((chunk) => chunk.dynamicImports ?? []));
  return [...dynamicEntries]
    .filter((key) => !first.has(key) && !key.startsWith('src/locales/') && !key.startsWith(LEVEL_TEXTS))
    .map((key) => ({
      source: key,
      gzipBytes: staticClosure(manifest, [key])
        .filter((part) => !first.has(part))
        .reduce((total, part) => total + gzipBytes(dist, manifest[part].file), 0),
    }))
    .sort((a, b) => b.gzipBytes - a.gzipBytes);
}

const kB = (bytes: number) => `${(bytes / 1024).toFixed(1)} kB`;

/** The report's lines and whether the load is within `budget`. */
export function checkFirstLoad(load: FirstLoad, budget = FIRST_LOAD_BUDGET_BYTES): { ok: boolean; lines: string[] } {
  const ok = load.gzipBytes <= budget;
  return {
    ok,
    lines: [
      ...load.files.map((file) => `  ${kB(file.gzipBytes).padStart(10)}  ${file.file}`),
      `First load (${load.locale}): ${kB(load.gzipBytes)} of JavaScript (gzip), budget ${kB(budget)}: ${ok ? 'within' : `OVER by ${kB(load.gzipBytes - budget)}`}.`,
    ],
  };
}

/** The lines listing what loads after the first screen, largest first. */
export function afterFirstScreenLines(parts: { source: string; gzipBytes: number }[]): string[] {
  return ['After the first screen, on demand:', ...parts.map((part) => `  ${kB(part.gzipBytes).padStart(10)}  ${part.source}`)];
}
