import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { LabOutcome, Vec3 } from '../../src/quest/code-labs/code-lab-grading.ts';
import { DIRECTIONS_PER_NORMAL, meanBrightness, renderCosineWithLearner } from '../../src/quest/code-labs/lab-render/cosine-render.ts';
import { labRenderScene } from '../../src/quest/code-labs/lab-render/lab-render-scene.ts';
import type { AskLearner } from '../../src/quest/code-labs/lab-render/render-passes.ts';
import { POINT_SETS, renderSamplesWithLearner } from '../../src/quest/code-labs/lab-render/samples-render.ts';
import { parseLevelJson } from '../../src/quest/level-schema.ts';
import { sandboxSeededRandom } from '../support/sandbox-random.ts';

/*
 * Rendering with a random function: the samples lab's points per pixel and the cosine lab's
 * bounce directions. The learner's functions here are written as a learner would, and called
 * as the sandbox calls them: on structured copies, with the sandbox's seeded random
 * (Mulberry32, public/code-lab-sandbox.html) for { seededRandom }.
 */

const levelScene = (id: string) => {
  const parsed = parseLevelJson(readFileSync(new URL(`../../levels/${id}.level.json`, import.meta.url), 'utf8'));
  if (!parsed.ok) throw new Error(`level ${id} does not parse`);
  return parsed.level.scene;
};

/** The learner's function behind a sandbox: each call on copies of its arguments, a { seededRandom } made into a random; the batches counted. */
function sandboxFor(learner: (...args: never[]) => unknown) {
  const batches: number[] = [];
  const ask: AskLearner = (calls) => {
    batches.push(calls.length);
    const outcomes = calls.map((args): LabOutcome => {
      try {
        const made = structuredClone(args).map((arg) =>
          typeof arg === 'object' && arg !== null && 'seededRandom' in arg ? sandboxSeededRandom(arg.seededRandom as number) : arg,
        );
        return { returned: structuredClone(learner(...(made as never[]))) };
      } catch (error) {
        return { threw: String(error), line: null };
      }
    });
    return Promise.resolve({ outcomes });
  };
  return { ask, batches };
}

type PixelSamples = (n: number, random: () => number) => { x: number; y: number }[];

/** Jittered samples as Shirley & Marschner §13.4.1 write them; `columnsFirst`: the cells visited column by column and y drawn before x. */
const jitteredWith =
  (columnsFirst = false): PixelSamples =>
  (n, random) => {
    const cells = Math.round(Math.sqrt(n));
    const points = [];
    for (let a = 0; a < cells; a++)
      for (let b = 0; b < cells; b++) {
        const [i, j] = columnsFirst ? [a, b] : [b, a];
        const [v, u] = columnsFirst ? [random(), random()] : [0, 0].map(random);
        points.push({ x: (i + u!) / cells, y: (j + v!) / cells });
      }
    return points;
  };

const WRONG_SAMPLES: Record<string, PixelSamples> = {
  'every point at the pixel’s centre': (n) => Array.from({ length: n }, () => ({ x: 0.5, y: 0.5 })),
  'all points in the first cell': (n, random) => Array.from({ length: n }, () => ({ x: random() / Math.sqrt(n), y: random() / Math.sqrt(n) })),
  'the cells twice too large, reaching outside the pixel': (n, random) => jitteredWith()(n, random).map(({ x, y }) => ({ x: 2 * x, y: 2 * y })),
};

const WIDTH = 160;
const HEIGHT = 120;

/** The mean |mine − reference| per channel of the two linear pictures, and their mean brightnesses' ratio. */
function compared(result: Awaited<ReturnType<typeof renderSamplesWithLearner>>) {
  if (result.kind !== 'rendered') throw new Error(`not rendered: ${result.kind}`);
  let sum = 0;
  for (let i = 0; i < result.mine.length; i++) sum += Math.abs(result.mine[i]! - result.reference[i]!);
  return { meanDifference: sum / result.mine.length, brightness: meanBrightness(result.mine, 0) / meanBrightness(result.reference, 0) };
}

describe('rendering the samples lab’s level with the learner’s points', () => {
  const scene = labRenderScene(levelScene('11-anti-aliasing'));

  it('asks for the point sets in one batch; a correct function, in either order of cells, differs from the tracer’s only in noise', async () => {
    for (const columnsFirst of [false, true]) {
      const { ask, batches } = sandboxFor(jitteredWith(columnsFirst));
      const { meanDifference, brightness } = compared(await renderSamplesWithLearner(scene, ask, WIDTH, HEIGHT, 11));
      expect(batches).toEqual([POINT_SETS]);
      // Measured: 0.0012 (jittered edges against jittered edges), mean brightness within 0.003 %.
      expect(meanDifference).toBeLessThan(0.002);
      expect(meanDifference).toBeGreaterThan(0);
      expect(Math.abs(brightness - 1)).toBeLessThan(0.005);
    }
  });

  for (const [mistake, learner] of Object.entries(WRONG_SAMPLES)) {
    it(`${mistake}: the edges differ from the tracer’s several times more`, async () => {
      // Measured: 0.006 (centre), 0.008 (first cell), 0.008 (outside).
      expect(compared(await renderSamplesWithLearner(scene, sandboxFor(learner).ask, WIDTH, HEIGHT, 11)).meanDifference).toBeGreaterThan(0.004);
    });
  }

  it('stops at a call whose answer it cannot use', async () => {
    const tooFew = await renderSamplesWithLearner(scene, sandboxFor((n: number, random: () => number) => jitteredWith()(n, random).slice(1)).ask, 8, 6, 11);
    expect(tooFew).toMatchObject({ kind: 'bad-answer', call: 0, failure: { check: 'wrong-count', got: 15, wanted: 16 } });
    const throws = await renderSamplesWithLearner(
      scene,
      sandboxFor(() => {
        throw new TypeError('cells is not defined');
      }).ask,
      8,
      6,
      11,
    );
    expect(throws).toMatchObject({ kind: 'bad-answer', call: 0, failure: { check: 'threw', message: 'TypeError: cells is not defined' } });
  });
});

type CosineDirection = (normal: Vec3, random: () => number) => Vec3;

const cross = (a: Vec3, b: Vec3): Vec3 => ({ x: a.y * b.z - a.z * b.y, y: a.z * b.x - a.x * b.z, z: a.x * b.y - a.y * b.x });
const unit = (a: Vec3): Vec3 => {
  const length = Math.hypot(a.x, a.y, a.z);
  return { x: a.x / length, y: a.y / length, z: a.z / length };
};

/** A direction at height z above the surface and angle φ around the normal, in a frame built on it. */
function around(normal: Vec3, z: number, phi: number): Vec3 {
  const t = unit(cross(Math.abs(normal.x) > 0.9 ? { x: 0, y: 1, z: 0 } : { x: 1, y: 0, z: 0 }, normal));
  const b = cross(normal, t);
  const r = Math.sqrt(Math.max(0, 1 - z * z));
  const [x, y] = [r * Math.cos(phi), r * Math.sin(phi)];
  return { x: t.x * x + b.x * y + normal.x * z, y: t.y * x + b.y * y + normal.y * z, z: t.z * x + b.z * y + normal.z * z };
}

/** Malley's method with a polar map (pbrt-v4 §A.5.3): r = √u, so z = √(1 − u). */
const malley: CosineDirection = (normal, random) => around(normal, Math.sqrt(1 - random()), 2 * Math.PI * random());
/** Every direction of the hemisphere alike (density 1/(2π)), weighted by the render as if it were cos θ / π. */
const uniformHemisphere: CosineDirection = (normal, random) => around(normal, random(), 2 * Math.PI * random());
/** The whole sphere: half of the directions go into the surface. */
const wholeSphere: CosineDirection = (_normal, random) => {
  const z = 2 * random() - 1;
  const phi = 2 * Math.PI * random();
  const r = Math.sqrt(1 - z * z);
  return { x: r * Math.cos(phi), y: r * Math.sin(phi), z };
};

const SIZE = 64;

describe('rendering the cosine lab’s level with the learner’s bounces', () => {
  const scene = levelScene('23-better-guesses');

  async function brightnessRatio(learner: CosineDirection) {
    const { ask, batches } = sandboxFor(learner);
    const result = await renderCosineWithLearner(scene, ask, SIZE, SIZE, 23);
    if (result.kind !== 'rendered') throw new Error(`not rendered: ${result.kind}`);
    return { ratio: meanBrightness(result.mine, 0) / meanBrightness(result.reference, 0), batches };
  }

  it('a correct function gives the tracer’s mean brightness within the noise, asked in one batch per normal met', async () => {
    const { ratio, batches } = await brightnessRatio(malley);
    // Measured: 0.7 % brighter; nine normals, the walls' and the box's faces the paths meet.
    expect(Math.abs(ratio - 1)).toBeLessThan(0.05);
    expect(batches).toHaveLength(1);
    expect(batches[0]! / DIRECTIONS_PER_NORMAL).toBe(9);
  });

  it('uniform directions come out darker; directions into the surface darker still', async () => {
    // Measured: 14 % and 33 % darker.
    expect((await brightnessRatio(uniformHemisphere)).ratio).toBeLessThan(0.92);
    expect((await brightnessRatio(wholeSphere)).ratio).toBeLessThan(0.8);
  });

  it('stops at a direction not of length 1, naming its normal', async () => {
    const twice: CosineDirection = (normal, random) => {
      const d = malley(normal, random);
      return { x: 2 * d.x, y: 2 * d.y, z: 2 * d.z };
    };
    const result = await renderCosineWithLearner(scene, sandboxFor(twice).ask, 8, 8, 23);
    expect(result).toMatchObject({ kind: 'bad-answer', problem: { kind: 'not-unit', length: expect.closeTo(2, 9) } });
  });

  it('lets timers run between bands of rows', async () => {
    let rendering = true;
    let turns = 0;
    const count = () => {
      if (!rendering) return;
      turns++;
      setTimeout(count, 0);
    };
    setTimeout(count, 0);
    await renderCosineWithLearner(scene, sandboxFor(malley).ask, SIZE, SIZE, 23);
    rendering = false;
    // Two renders of 64 rows in bands of 8: the page had a turn about 14 times.
    expect(turns).toBeGreaterThanOrEqual(10);
  });
});
