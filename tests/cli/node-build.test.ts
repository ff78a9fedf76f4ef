import { afterAll, describe, expect, it } from 'vitest';
import { execFile } from 'node:child_process';
import { mkdir, readdir, readFile, rm, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
// @ts-expect-error: a plain JavaScript build script without type declarations
import { buildNode, staleReason } from '../../scripts/node-build.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** A build of its own, two folders below the root like the real one (its relative paths need that). */
const DIR = join(ROOT, 'build', `test-${process.pid}`);

afterAll(() => rm(DIR, { recursive: true, force: true }));

describe('the prebuilt rt command', () => {
  it('is stale before it is built, up to date after, and stale again once an input is newer', async () => {
    expect(await staleReason(DIR)).toBe('there is no build yet');
    await buildNode(DIR);
    expect(await staleReason(DIR)).toBeNull();

    const recordFile = join(DIR, 'inputs.json');
    const record = JSON.parse(await readFile(recordFile, 'utf8'));
    expect(record.inputs).toContain(join(ROOT, 'src/tracer/whitted-integrator.ts'));
    // As if every input had been saved after the build.
    await writeFile(recordFile, JSON.stringify({ ...record, builtAt: 0 }));
    expect(await staleReason(DIR)).toMatch(/ changed$/);
  }, 60_000);

  it("empties the command's model cache, which the previous build's parser and BVH builder made", async () => {
    const meshCache = join(DIR, 'mesh-cache');
    await mkdir(meshCache, { recursive: true });
    await writeFile(join(meshCache, 'capsule.mesh'), 'made by an older build');
    await buildNode(DIR, meshCache);
    await expect(readdir(meshCache)).rejects.toThrow(/ENOENT/);
  }, 60_000);

  it('runs without TypeScript: its help, and a render whose worker threads run the build too', async () => {
    await buildNode(DIR);
    const run = (...args: string[]) => promisify(execFile)('node', [join(DIR, 'rt.mjs'), ...args], { cwd: ROOT });
    expect((await run('--help')).stdout).toContain('Usage:');
    const out = join(DIR, 'tiny.png');
    const { stdout } = await run('render', 'introduction', '--out', out, '--width', '8', '--height', '8', '--workers', '1', '--stats');
    expect(JSON.parse(stdout.trim().split('\n').at(-1) ?? '')).toMatchObject({ workers: 1, rays: { primary: 64 } });
    // The build's own modules only: nothing in it refers to a TypeScript file or to tsx.
    const worker = await readFile(join(DIR, 'render-worker.mjs'), 'utf8');
    expect(worker).not.toMatch(/tsx|\.ts['"]/);
  }, 60_000);
});
