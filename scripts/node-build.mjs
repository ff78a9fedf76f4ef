// The `rt` command's prebuilt JavaScript: src/cli/rt.ts and its render worker bundled by
// esbuild into build/node/, so that neither the command nor its worker threads compile
// TypeScript when they start (compiling with tsx cost about 1.5 s of every run).
//
// Built by `npm ci` / `npm install` (the prepare script) and again by bin/rt.mjs whenever
// the build is missing or one of its inputs is newer than it. Plain JavaScript on purpose:
// it runs before anything can compile TypeScript.
//
// The output sits two folders below the project's root, as the sources do (src/cli/,
// src/scene/), so their `new URL('../../levels/', import.meta.url)` paths stay right.
import { mkdir, readdir, readFile, rename, rm, stat, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
export const BUILD_DIR = join(ROOT, 'build', 'node');
/** The command's entry in the build; bin/rt.mjs imports it. */
export const RT_ENTRY = join(BUILD_DIR, 'rt.mjs');
/**
 * The command's parsed models with their BVHs (src/cli/mesh-cache.ts, MESH_CACHE_DIR): made by
 * the parser and BVH builder of the build that wrote them, so a new build starts without them.
 */
const MESH_CACHE_DIR = join(ROOT, 'build', 'mesh-cache');
/** Every file the build was made from, with the build's time: what the staleness check reads. */
const inputsFile = (dir) => join(dir, 'inputs.json');

const ENTRIES = {
  rt: 'src/cli/rt.ts',
  // Its name is fixed: src/cli/render-worker-thread.ts starts it by this name from the build.
  'render-worker': 'workers/render.worker.node.ts',
};

/**
 * Bundles the entries (packages included, tree-shaken) into `dir` and records their inputs.
 * `dir` must be two folders below the root (see above); tests build into one of their own.
 * `meshCache`, the folder of the command's cached models, is emptied (the real build's
 * folder for the real build, none for others unless given).
 */
export async function buildNode(dir = BUILD_DIR, meshCache = dir === BUILD_DIR ? MESH_CACHE_DIR : null) {
  const { build } = await import('esbuild');
  const started = Date.now();
  const result = await build({
    absWorkingDir: ROOT,
    entryPoints: ENTRIES,
    outdir: dir,
    outExtension: { '.js': '.mjs' },
    bundle: true,
    // The commands are loaded on use (src/cli/rt.ts), so each is a chunk of its own.
    splitting: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    metafile: true,
    write: false,
    logLevel: 'warning',
    external: ['pngjs'],
  });
  await mkdir(dir, { recursive: true });
  // Each file is written beside its place and renamed into it, so a command started while
  // another one rebuilds reads either the old file or the new one, never half of one.
  const isEntry = (path) => path === join(dir, 'rt.mjs');
  // The command last: it starts the worker, which is then already the new one.
  const files = [...result.outputFiles].sort((a, b) => Number(isEntry(a.path)) - Number(isEntry(b.path)));
  for (const file of files) {
    const temporary = `${file.path}.${process.pid}.tmp`;
    await writeFile(temporary, file.contents);
    await rename(temporary, file.path);
  }
  // Chunk names carry a hash of their content: the previous build's chunks are dropped.
  const written = new Set(files.map((file) => file.path));
  for (const name of await readdir(dir)) {
    if (name.endsWith('.mjs') && !written.has(join(dir, name))) await rm(join(dir, name), { force: true });
  }
  if (meshCache) await rm(meshCache, { recursive: true, force: true });
  const inputs = Object.keys(result.metafile.inputs).map((input) => join(ROOT, input));
  inputs.push(fileURLToPath(import.meta.url), join(ROOT, 'tsconfig.json'));
  const temporary = `${inputsFile(dir)}.${process.pid}.tmp`;
  await writeFile(temporary, JSON.stringify({ builtAt: started, inputs }));
  await rename(temporary, inputsFile(dir));
}

/**
 * Why the build must be made again, or null when it is up to date: missing, or an input
 * changed after the build started (a file deleted since counts as changed).
 */
export async function staleReason(dir = BUILD_DIR) {
  let recorded;
  try {
    recorded = JSON.parse(await readFile(inputsFile(dir), 'utf8'));
  } catch {
    return 'there is no build yet';
  }
  const times = await Promise.all(
    recorded.inputs.map((input) =>
      stat(input).then(
        (s) => s.mtimeMs,
        () => Infinity,
      ),
    ),
  );
  const changed = recorded.inputs.find((_, i) => times[i] >= recorded.builtAt);
  return changed === undefined ? null : `${changed} changed`;
}

/** Builds when the build is missing or stale; quick (one stat per input) when it is not. */
export async function ensureNodeBuild() {
  if ((await staleReason()) !== null) await buildNode();
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  await buildNode();
  console.log(`built ${BUILD_DIR}`);
}
