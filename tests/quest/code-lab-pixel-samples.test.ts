import { describe, expect, it } from 'vitest';
import { chiSquare, upperGamma } from '../../src/quest/code-labs/chi-square.ts';
import { gradeSamples, sampleTally, type Point } from '../../src/quest/code-labs/code-lab-statistics.ts';
import { PIXEL_SAMPLES_SIGNIFICANCE, pixelSampleRuns, tracerPixelSamples } from '../../src/quest/code-labs/pixel-samples-lab.ts';
import { runCases } from '../support/code-lab-run.ts';
import { sandboxRandomSource, sandboxSeededRandom } from '../support/sandbox-random.ts';

type PixelSamples = (n: number, random: () => number) => unknown;

const SIZES = [1, 4, 9, 16, 64];

function grade(pixelSamples: PixelSamples, seed = 11) {
  const runs = pixelSampleRuns(SIZES, 100, seed);
  return gradeSamples(
    runs,
    runCases(
      pixelSamples,
      runs.map((run) => run.args),
    ),
    PIXEL_SAMPLES_SIGNIFICANCE,
  );
}

/** The textbook loop (Shirley & Marschner §13.4.1), with the ways learners get it wrong. */
function jittered(place: (i: number, j: number, cells: number, random: () => number) => Point): PixelSamples {
  return (n, random) => {
    const cells = Math.round(Math.sqrt(n));
    const points: Point[] = [];
    for (let j = 0; j < cells; j++) for (let i = 0; i < cells; i++) points.push(place(i, j, cells, random));
    return points;
  };
}

const correct = jittered((i, j, cells, random) => ({ x: (i + random()) / cells, y: (j + random()) / cells }));

describe('the jittered samples lab', () => {
  it('passes a correct function and the tracer’s own jittered pattern with any of 50 seeds', () => {
    for (let seed = 0; seed < 50; seed++) {
      for (const pixelSamples of [correct, tracerPixelSamples]) {
        const report = grade(pixelSamples, seed);
        expect(report.firstFailure, `seed ${seed}`).toBeNull();
        expect(report.test!.p).toBeGreaterThanOrEqual(PIXEL_SAMPLES_SIGNIFICANCE);
        expect(sampleTally(report)).toEqual({ passed: 102, total: 102, failed: null });
      }
    }
  });

  it.each([
    [
      'plain random points, not stratified',
      (n: number, random: () => number) => Array.from({ length: n }, () => ({ x: random(), y: random() })),
      'two-in-a-cell',
    ],
    ['every point at its cell’s centre', jittered((i, j, cells) => ({ x: (i + 0.5) / cells, y: (j + 0.5) / cells })), 'uneven-within-cells'],
    ['only x jittered', jittered((i, j, cells, random) => ({ x: (i + random()) / cells, y: (j + 0.5) / cells })), 'uneven-within-cells'],
    [
      'a place in the cell biased toward its corner',
      jittered((i, j, cells, random) => ({ x: (i + random() * random()) / cells, y: (j + random()) / cells })),
      'uneven-within-cells',
    ],
    [
      'cells picked at random, so visited unevenly',
      jittered((_i, _j, cells, random) => ({ x: (Math.floor(random() * cells) + random()) / cells, y: (Math.floor(random() * cells) + random()) / cells })),
      'two-in-a-cell',
    ],
    ['the diagonal cells only', jittered((i, _j, cells, random) => ({ x: (i + random()) / cells, y: (i + random()) / cells })), 'two-in-a-cell'],
    [
      'a grid one cell too wide',
      jittered((i, j, cells, random) => ({ x: (i + random()) / Math.max(1, cells - 1), y: (j + random()) / cells })),
      'outside-pixel',
    ],
    ['Math.random instead of the given random', jittered((i, j, cells) => ({ x: (i + Math.random()) / cells, y: (j + Math.random()) / cells })), 'not-seeded'],
  ])('fails a function with %s on its named check', (_name, pixelSamples, check) => {
    for (const seed of [1, 11, 99]) {
      const report = grade(pixelSamples as PixelSamples, seed);
      expect(report.firstFailure?.check).toBe(check);
      expect(sampleTally(report).passed).toBeLessThan(sampleTally(report).total);
    }
  });

  it('names a wrong answer, a wrong count and an exception with their run', () => {
    expect(grade(() => 4).firstFailure).toEqual({ check: 'not-points', run: 0, got: 'number' });
    expect(grade((n, random) => String(correct(n, random))).firstFailure).toMatchObject({ check: 'not-points', run: 0, got: 'string' });
    expect(grade((n, random) => (correct(n, random) as Point[]).slice(1)).firstFailure).toEqual({ check: 'wrong-count', run: 0, got: 0, wanted: 1 });
    expect(
      grade((n, random) => {
        if (n === 9) throw new Error('oops');
        return correct(n, random);
      }).firstFailure,
    ).toMatchObject({ check: 'threw', run: 2 });
  });

  it('computes χ² p-values as the tables give them', () => {
    // 95th and 99.9th percentiles of χ² with 63 degrees of freedom; the 99th with 10.
    expect(upperGamma(63 / 2, 82.529 / 2)).toBeCloseTo(0.05, 4);
    expect(upperGamma(63 / 2, 103.442 / 2)).toBeCloseTo(0.001, 5);
    expect(upperGamma(10 / 2, 23.209 / 2)).toBeCloseTo(0.01, 5);
    expect(chiSquare([10, 10, 10, 10], [10, 10, 10, 10])).toEqual({ value: 0, degrees: 3, p: 1 });
  });
});

describe('the sandbox page’s seeded random', () => {
  // The function as public/code-lab-sandbox.html defines it, run here: the numbers the learner's function gets.
  const source = sandboxRandomSource;
  const seededRandom = sandboxSeededRandom;

  it('gives the same numbers for the same seed, uniform in [0, 1)', () => {
    expect(source).toContain('Math.imul');
    const first = seededRandom(7);
    const again = seededRandom(7);
    const numbers = Array.from({ length: 20000 }, () => first());
    expect(numbers.slice(0, 5)).toEqual(Array.from({ length: 5 }, () => again()));
    expect(numbers.every((u) => u >= 0 && u < 1)).toBe(true);
    const counts = new Array<number>(20).fill(0);
    for (const u of numbers) counts[Math.floor(u * 20)]!++;
    expect(chiSquare(counts, new Array<number>(20).fill(1000)).p).toBeGreaterThan(1e-4);
  });

  it('lets a correct function pass with any of 50 seeds', () => {
    for (let seed = 0; seed < 50; seed++) {
      const runs = pixelSampleRuns(SIZES, 100, seed);
      const outcomes = runs.map((run) => ({ returned: correct(run.args[0], seededRandom(run.args[1].seededRandom)) }));
      expect(gradeSamples(runs, outcomes, PIXEL_SAMPLES_SIGNIFICANCE).firstFailure, `seed ${seed}`).toBeNull();
    }
  });
});
