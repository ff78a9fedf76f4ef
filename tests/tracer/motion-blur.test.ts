import { describe, expect, it } from 'vitest';
import type { TimePattern } from '../../src/scene/scene.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

/** Motion blur (distribution-effects §2): an object at position + τ·velocity at time τ. */

const W = 160;
const H = 40;
const FOV = 20;
const DISTANCE = 5;
const RADIUS = 0.25;
const START = -1;

/** A square of side 2·RADIUS turned to face the camera: a plane moves as the other shapes do (its own test in plane.ts). */
const FACING_SQUARE = { shape: 'plane', rotation: [90, 0, 0], scale: [2 * RADIUS, 1, 2 * RADIUS] };

function centreRow(velocity: number, timeSamples: number, timePattern: TimePattern = 'jittered', shape: Record<string, unknown> = {}): number[] {
  const scene = tracerSceneFrom({
    camera: { position: [0, 0, DISTANCE], target: [0, 0, 0], fov: FOV },
    settings: { background: [0, 0, 0], timeSamples, timePattern },
    objects: [
      {
        id: 'ball',
        shape: 'sphere',
        position: [START, 0, 0],
        velocity: [velocity, 0, 0],
        scale: [2 * RADIUS, 2 * RADIUS, 2 * RADIUS],
        material: matte([1, 1, 1], { ambient: 1, diffuse: 0 }),
        ...shape,
      },
    ],
  });
  const rgb = renderTile(scene, { x: 0, y: H / 2, width: W, height: 1 }, { imageWidth: W, imageHeight: H, seed: 9 });
  return Array.from({ length: W }, (_, x) => rgb[x * 3]);
}

/** The column whose centre sees world x on the plane z = 0 (pinhole projection). */
function column(x: number): number {
  const halfWidth = DISTANCE * Math.tan((FOV / 2) * (Math.PI / 180)) * (W / H);
  return ((x / halfWidth + 1) / 2) * W - 0.5;
}

function litRange(row: number[]): [number, number] {
  const lit = row.flatMap((value, x) => (value > 0 ? [x] : []));
  return [lit[0], lit[lit.length - 1]];
}

/** The runs of lit pixels in a row, as [first, last] columns. */
function litRuns(row: number[]): [number, number][] {
  const runs: [number, number][] = [];
  row.forEach((value, x) => {
    if (value === 0) return;
    const last = runs[runs.length - 1];
    if (last && last[1] === x - 1) last[1] = x;
    else runs.push([x, x]);
  });
  return runs;
}

/** The spread (standard deviation) of a row's values between two columns, around their mean. */
function spread(row: number[], from: number, to: number): number {
  const part = row.slice(from, to);
  const mean = part.reduce((sum, value) => sum + value, 0) / part.length;
  return Math.sqrt(part.reduce((sum, value) => sum + (value - mean) ** 2, 0) / part.length);
}

describe('motion blur', () => {
  it('a still object covers only its own pixels', () => {
    const [first, last] = litRange(centreRow(0, 16));
    expect(Math.abs(first - column(START - RADIUS))).toBeLessThanOrEqual(1);
    expect(Math.abs(last - column(START + RADIUS))).toBeLessThanOrEqual(1);
  });

  it('a moving plane covers the pixels from its start to its end, as a moving ball does', () => {
    const row = centreRow(2, 16, 'jittered', FACING_SQUARE);
    const [first, last] = litRange(row);
    expect(Math.abs(first - column(START - RADIUS))).toBeLessThanOrEqual(1);
    expect(Math.abs(last - column(START + 2 + RADIUS))).toBeLessThanOrEqual(1);
    for (let x = first; x <= last; x++) expect(row[x]).toBeGreaterThan(0);
    // Still, it covers only its own pixels.
    const [stillFirst, stillLast] = litRange(centreRow(0, 16, 'jittered', FACING_SQUARE));
    expect([Math.abs(stillFirst - column(START - RADIUS)), Math.abs(stillLast - column(START + RADIUS))].every((off) => off <= 1)).toBe(true);
  });

  for (const velocity of [2, -1.5]) {
    it(`with velocity ${velocity} m over 16 times it covers the pixels from its start to its end, without gaps`, () => {
      const row = centreRow(velocity, 16);
      const [first, last] = litRange(row);
      const from = Math.min(START, START + velocity) - RADIUS;
      const to = Math.max(START, START + velocity) + RADIUS;
      expect(Math.abs(first - column(from))).toBeLessThanOrEqual(1);
      expect(Math.abs(last - column(to))).toBeLessThanOrEqual(1);
      // Each step in time (|v|/16) is smaller than the ball: no gaps in the streak.
      for (let x = first; x <= last; x++) expect(row[x]).toBeGreaterThan(0);
      // A pixel in the middle of the streak sees the ball for 2r/|v| of the shutter.
      const middle = row.slice(Math.ceil(column(from + 2 * RADIUS)), Math.floor(column(to - 2 * RADIUS)));
      const mean = middle.reduce((sum, value) => sum + value, 0) / middle.length;
      expect(mean).toBeCloseTo((2 * RADIUS) / Math.abs(velocity), 1);
    });
  }

  it('one time sample sees the object where it starts, sharp', () => {
    const [first, last] = litRange(centreRow(2, 1));
    expect(Math.abs(first - column(START - RADIUS))).toBeLessThanOrEqual(1);
    expect(Math.abs(last - column(START + RADIUS))).toBeLessThanOrEqual(1);
  });

  // A ball 0.5 m wide moving 3 m: with 4 moments it moves 0.75 m between two of them.
  const FAR = 3;

  it('grid times: 4 moments give 4 separate copies, each 1/4 bright, at the middles of the 4 intervals (aliasing in time)', () => {
    const row = centreRow(FAR, 4, 'grid');
    const runs = litRuns(row);
    expect(runs).toHaveLength(4);
    runs.forEach(([first, last], i) => {
      const centre = START + ((i + 0.5) / 4) * FAR;
      expect(Math.abs(first - column(centre - RADIUS))).toBeLessThanOrEqual(1);
      expect(Math.abs(last - column(centre + RADIUS))).toBeLessThanOrEqual(1);
      for (let x = first + 1; x < last; x++) expect(row[x]).toBeCloseTo(0.25, 12);
    });
  });

  it("jittered times: the same 4 samples light pixels in the gaps between the grid's copies, unevenly (grain)", () => {
    const grid = centreRow(FAR, 4, 'grid');
    const jittered = centreRow(FAR, 4, 'jittered');
    const [first, last] = litRange(jittered);
    const gaps = grid.flatMap((value, x) => (value === 0 && x > first && x < last ? [x] : []));
    expect(gaps.length).toBeGreaterThan(10);
    expect(gaps.filter((x) => jittered[x] > 0).length).toBeGreaterThan(gaps.length / 4);
    // Not 4 clean copies: the streak's inside has dark pixels and lit ones side by side.
    expect(litRuns(jittered).length).toBeGreaterThan(4);
  });

  for (const pattern of ['jittered', 'random'] as const) {
    it(`${pattern} times: 16 samples give fainter grain than 4 (the spread around the mean shrinks)`, () => {
      const from = Math.ceil(column(START + 2 * RADIUS));
      const to = Math.floor(column(START + FAR - 2 * RADIUS));
      expect(spread(centreRow(FAR, 16, pattern), from, to)).toBeLessThan(0.7 * spread(centreRow(FAR, 4, pattern), from, to));
    });
  }
});
