/**
 * The whole `rt render` command, as a user runs it: process start, prebuilt JavaScript,
 * worker threads, scene, render and PNG. Wall time of a 16×16 render, median of several runs.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
const RUNS = 5;

/** Median wall milliseconds of `rt render <scene> --width 16 --height 16`, after one run that builds the command if needed. */
export function rtRender16Ms(scene: string): number {
  const dir = mkdtempSync(join(tmpdir(), 'rt-bench-'));
  try {
    const run = () => {
      const started = performance.now();
      execFileSync('node', ['bin/rt.mjs', 'render', scene, '--out', join(dir, 'tiny.png'), '--width', '16', '--height', '16'], { cwd: ROOT, stdio: 'ignore' });
      return performance.now() - started;
    };
    run();
    const times = Array.from({ length: RUNS }, run).sort((a, b) => a - b);
    return times[Math.floor(RUNS / 2)];
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}
