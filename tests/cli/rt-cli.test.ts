import { beforeAll, describe, expect, it } from 'vitest';
import { execFile } from 'node:child_process';
import { mkdtemp, readFile, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { PNG } from 'pngjs';
import { defaultScene } from '../../src/scene/scene-defaults.ts';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

interface Run {
  code: number;
  stdout: string;
  stderr: string;
}

/** Runs `node bin/rt.mjs …args` without a shell. */
async function rt(...args: string[]): Promise<Run> {
  try {
    const { stdout, stderr } = await promisify(execFile)('node', ['bin/rt.mjs', ...args], { cwd: ROOT });
    return { code: 0, stdout, stderr };
  } catch (error) {
    const failed = error as { code: number; stdout: string; stderr: string };
    return { code: failed.code, stdout: failed.stdout, stderr: failed.stderr };
  }
}

let dir = '';
const file = (name: string) => join(dir, name);

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'rt-cli-'));
  const scene = { ...defaultScene(), settings: { ...defaultScene().settings, supersampling: 2 } };
  await writeFile(file('scene.json'), JSON.stringify(scene));
  const level = JSON.parse(await readFile(join(ROOT, 'levels/01-introduction.level.json'), 'utf8'));
  level.scene.settings = { ...level.scene.settings, supersampling: 2 };
  await writeFile(file('level.json'), JSON.stringify(level));
  await writeFile(file('bad-fov.json'), JSON.stringify({ version: 1, camera: { fov: 400 } }));
  await writeFile(file('bad-level.json'), JSON.stringify({ ...level, scene: { ...level.scene, camera: { ...level.scene.camera, fov: 0 } } }));
  await writeFile(file('broken.json'), '{"version": 1,');
});

describe('rt render', () => {
  it('writes a PNG of the requested size and prints the stats line last', async () => {
    const out = file('out.png');
    const run = await rt('render', file('scene.json'), '--out', out, '--width', '64', '--height', '48', '--workers', '2', '--stats');

    expect(run).toMatchObject({ code: 0, stderr: '' });
    const png = PNG.sync.read(await readFile(out));
    expect([png.width, png.height]).toEqual([64, 48]);
    const stats = JSON.parse(run.stdout.trim().split('\n').at(-1) ?? '');
    expect(stats).toMatchObject({ workers: 2, rays: { primary: 64 * 48 * 4 } });
    expect(Object.keys(stats)).toEqual(['ms', 'workers', 'rays']);
    const { primary, shadow, reflect, refract, total } = stats.rays;
    expect(total).toBe(primary + shadow + reflect + refract);
  });

  it('accepts --force, and never starts more workers than the image has tiles', async () => {
    const run = await rt('render', file('scene.json'), '--out', file('tiny.png'), '--width', '8', '--height', '6', '--workers', '2', '--force', '--stats');
    expect(run).toMatchObject({ code: 0, stderr: '' });
    expect(JSON.parse(run.stdout.trim().split('\n').at(-1) ?? '')).toMatchObject({ workers: 1 });
  });

  // On 2 or more cores (as in CI), where the default once started one worker per core.
  it('starts one worker for a small render when --workers is not given', async () => {
    const run = await rt('render', file('scene.json'), '--out', file('small.png'), '--width', '64', '--height', '48', '--stats');
    expect(run).toMatchObject({ code: 0, stderr: '' });
    expect(JSON.parse(run.stdout.trim().split('\n').at(-1) ?? '')).toMatchObject({ workers: 1, rays: { primary: 64 * 48 * 4 } });
  });

  it('keeps the aspect ratio when given only a width, and renders a level file’s scene', async () => {
    const out = file('level.png');
    const run = await rt('render', file('level.json'), '--out', out, '--width', '32');

    expect(run.code).toBe(0);
    const png = PNG.sync.read(await readFile(out));
    expect([png.width, png.height]).toEqual([32, 24]);
  });
});

describe('rt trace', () => {
  it('prints the pixel’s ray tree as JSON, one root per supersample', async () => {
    const run = await rt('trace', file('scene.json'), '--pixel', '3,2');

    expect(run.code).toBe(0);
    const trace = JSON.parse(run.stdout);
    expect(trace.pixel).toEqual([3, 2]);
    expect(trace.color).toHaveLength(3);
    expect(trace.rays).toHaveLength(4);
    expect(trace.rays[0]).toMatchObject({ type: 'primary', children: expect.any(Array) });
    expect(JSON.stringify(trace)).not.toContain('"terms"');
  });

  it('adds every hit’s shading terms with --terms, summing to the ray’s colour', async () => {
    const run = await rt('trace', file('scene.json'), '--pixel', '3,3', '--terms');

    expect(run.code).toBe(0);
    const root = JSON.parse(run.stdout).rays[0];
    expect(root.hit).toBe(true);
    expect(root.terms).toMatchObject({ ambient: expect.any(Array), lights: expect.any(Array), sum: expect.any(Array) });
    for (let c = 0; c < 3; c++) expect(Math.min(1, Math.max(0, root.terms.sum[c]))).toBe(root.color[c]);
  });
});

describe('rt validate', () => {
  it('exits 0 when every file is valid', async () => {
    const run = await rt('validate', file('scene.json'), file('level.json'));
    expect(run).toMatchObject({ code: 0, stderr: '' });
  });

  it('checks the level index and every level it lists; a render of the index is refused', async () => {
    expect(await rt('validate', 'levels/index.json')).toMatchObject({ code: 0, stderr: '' });
    const render = await rt('render', 'levels/index.json', '--out', file('index.png'));
    expect(render.code).toBe(1);
    expect(render.stderr.trim()).toBe('rt: levels/index.json: this is the level index, not a scene: name one level');
  });

  it('exits 1 and lists every problem as file: path: reason', async () => {
    const run = await rt('validate', file('scene.json'), file('bad-fov.json'), file('bad-level.json'), file('broken.json'), file('missing.json'));

    expect(run.code).toBe(1);
    expect(run.stderr.trim().split('\n')).toEqual([
      `${file('bad-fov.json')}: camera.fov: must be between 1 and 179, got 400`,
      `${file('bad-level.json')}: scene.camera.fov: must be between 1 and 179, got 0`,
      expect.stringMatching(/^.*broken\.json: \(root\): not valid JSON at line 1/),
      `${file('missing.json')}: cannot read: no such file or folder`,
    ]);
  });
});

describe('rt with bad input or asking for help', () => {
  const cases: [string, () => string[], number, RegExp][] = [
    ['no command', () => [], 2, /no command/],
    ['an unknown command', () => ['paint'], 2, /unknown command "paint"/],
    ['an unknown option', () => ['render', file('scene.json'), '--out', file('x.png'), '--fast'], 2, /unknown option --fast/],
    ['a prototype key as an option', () => ['render', file('scene.json'), '--out', file('x.png'), '--constructor'], 2, /unknown option --constructor/],
    ['__proto__ as an option', () => ['trace', file('scene.json'), '--pixel', '0,0', '--__proto__', 'x'], 2, /unknown option --__proto__/],
    ['a missing --out', () => ['render', file('scene.json')], 2, /missing --out/],
    [
      'an --out that is neither PNG nor PFM',
      () => ['render', file('scene.json'), '--out', file('x.jpg')],
      2,
      /--out must name a \.png or a \.pfm file, the formats rt writes, got ".*x\.jpg"/,
    ],
    [
      'far more workers than cores',
      () => ['render', file('scene.json'), '--out', file('x.png'), '--workers', '100000'],
      2,
      /--workers must be a whole number from 1 to \d+, got "100000"/,
    ],
    [
      'a render the estimate puts at hours',
      () => ['render', file('scene.json'), '--out', file('x.png'), '--width', '4096', '--height', '4096', '--workers', '1'],
      1,
      /this render would take about \d+ (minutes|hours) on 1 worker \(.* rays\): give --force to render it anyway; lighter: settings\.supersampling 1 \(about \d+ seconds\), or --width \d+ --height \d+/,
    ],
    ['a malformed --width', () => ['render', file('scene.json'), '--out', file('x.png'), '--width', 'wide'], 2, /--width must be a whole number/],
    [
      'a negative --width',
      () => ['render', file('scene.json'), '--out', file('x.png'), '--width', '-5'],
      2,
      /--width must be a whole number from 1 to 4096, got "-5"/,
    ],
    ['an option where a value belongs', () => ['render', file('scene.json'), '--width', '--out', file('x.png')], 2, /--width needs a value/],
    ['a malformed --pixel', () => ['trace', file('scene.json'), '--pixel', '3;2'], 2, /--pixel must be/],
    ['validate without files', () => ['validate'], 2, /give one or more files/],
    ['a missing file', () => ['render', file('missing.json'), '--out', file('x.png')], 1, /missing\.json: cannot read/],
    ['bad JSON', () => ['render', file('broken.json'), '--out', file('x.png')], 1, /not valid JSON/],
    ['a schema error', () => ['trace', file('bad-fov.json'), '--pixel', '0,0'], 1, /camera\.fov: must be between 1 and 179/],
    ['an unknown level', () => ['render', 'no-such-level', '--out', file('x.png')], 1, /no scene file or level "no-such-level"/],
    ['an unwritable --out', () => ['render', file('scene.json'), '--out', join(dir, 'no-folder', 'x.png')], 1, /cannot write/],
    ['a pixel off the screen', () => ['trace', file('scene.json'), '--pixel', '8,0'], 1, /outside the 8×6 camera pixels/],
  ];

  it.concurrent.for(cases)('%s gives one message and the right exit code', async ([, args, code, message], { expect }) => {
    const run = await rt(...args());

    expect(run.code).toBe(code);
    expect(run.stderr).toMatch(message);
    expect(run.stderr.trim().split('\n')).toHaveLength(1);
    expect(run.stderr).not.toMatch(/^\s+at /m);
  });

  it.concurrent.for([['--help'], ['render', '--help'], ['trace', '-h'], ['validate', '--help']])('prints help for rt %s', async (args, { expect }) => {
    const run = await rt(...args);
    expect(run.code).toBe(0);
    expect(run.stdout).toMatch(/Usage/);
  });
});
