import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

/**
 * The layers of README.md's architecture, lowest first. A file may import from its own layer
 * and from lower ones, never from a higher one or a sibling of the same rank: the pure core
 * (util, scene, tracer, lab-state, quest, classroom) never reaches up into rendering, the
 * view or the UI, and a UI feature never reaches into another feature of its rank.
 */
const LAYERS: Record<string, number> = {
  'src/util': 0,
  'src/scene': 1,
  'src/tracer': 2,
  workers: 3,
  'src/lab-state': 3,
  'src/quest': 4,
  'src/render': 4,
  'src/debugger': 4,
  'src/locales': 4,
  'src/i18n': 5,
  'src/classroom': 5,
  'src/view': 6,
  'src/app': 7,
  'src/cli': 7,
  'src/ui/controls': 8,
  'src/ui/game': 9,
  'src/ui/classroom': 9,
  'src/ui/lab': 10,
  'src/ui/shell': 11,
  'src/main.ts': 12,
};

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

/** The layer a repository path belongs to: the longest listed folder it is in. */
export function layerOf(path: string): string | undefined {
  return Object.keys(LAYERS)
    .filter((layer) => path === layer || path.startsWith(`${layer}/`))
    .sort((a, b) => b.length - a.length)[0];
}

/** Relative module specifiers of a file: static imports and exports, and import() calls. */
export function importsOf(text: string): string[] {
  const found = text.matchAll(
    /(?:^|\n)\s*(?:import|export)\s[^'"]*?from\s*['"](\.[^'"]+)['"]|(?:^|\n)\s*import\s*['"](\.[^'"]+)['"]|import\(\s*['"](\.[^'"]+)['"]\s*\)/g,
  );
  return [...found].map((match) => match[1] ?? match[2] ?? match[3] ?? '');
}

/** Every import that goes to a higher layer or a sibling, as "from -> to". */
export function upwardImports(files: { path: string; text: string }[]): string[] {
  const wrong: string[] = [];
  for (const { path, text } of files) {
    const from = layerOf(path);
    if (!from) continue;
    for (const specifier of importsOf(text)) {
      const target = relative(ROOT, resolve(ROOT, dirname(path), specifier))
        .split('\\')
        .join('/');
      const to = layerOf(target);
      if (!to || to === from) continue;
      if (LAYERS[to]! >= LAYERS[from]!) wrong.push(`${path} -> ${target}`);
    }
  }
  return wrong;
}

function sourceFiles(folder: string): string[] {
  return readdirSync(join(ROOT, folder)).flatMap((name) => {
    const path = `${folder}/${name}`;
    if (statSync(join(ROOT, path)).isDirectory()) return sourceFiles(path);
    return /\.(ts|mjs)$/.test(name) ? [path] : [];
  });
}

describe('the layers', () => {
  it('no file imports from a higher layer or a sibling of its rank', () => {
    const files = [...sourceFiles('src'), ...sourceFiles('workers')].map((path) => ({ path, text: readFileSync(join(ROOT, path), 'utf8') }));
    expect(files.length).toBeGreaterThan(200);
    expect(upwardImports(files)).toEqual([]);
  });

  it('catches an upward import, a sibling import and a dynamic one, and allows a downward one', () => {
    const files = [
      { path: 'src/quest/goal.ts', text: "import type { LabState } from '../lab-state/lab-state.ts';\nimport { Store } from '../app/store.ts';" },
      { path: 'src/render/pool.ts', text: "import { x } from '../quest/goal.ts';" },
      { path: 'src/tracer/a.ts', text: "const lazy = () => import('../ui/lab/rt-lab.ts');" },
      { path: 'src/ui/lab/panels/p.ts', text: "import '../../controls/rt-slider.ts';\nimport { storeContext } from '../store-context.ts';" },
    ];
    expect(upwardImports(files)).toEqual([
      'src/quest/goal.ts -> src/app/store.ts',
      'src/render/pool.ts -> src/quest/goal.ts',
      'src/tracer/a.ts -> src/ui/lab/rt-lab.ts',
    ]);
  });

  it('knows the layer of every source folder', () => {
    const folders = [...new Set([...sourceFiles('src'), ...sourceFiles('workers')].map((path) => dirname(path)))];
    expect(folders.filter((folder) => folder !== 'src' && layerOf(folder) === undefined)).toEqual([]);
  });
});
