import { describe, expect, it } from 'vitest';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { matte, tracerSceneFrom } from '../support/test-scene.ts';

/** Motion blur (distribution-effects §2): an object at position + τ·velocity at time τ. */

const W = 160;
const H = 40;
const FOV = 20;
const DISTANCE = 5;
const RADIUS = 0.25;
const START = -1;

function centreRow(velocity: number, timeSamples: number): number[] {
  const scene = tracerSceneFrom({
    camera: { position: [0, 0, DISTANCE], target: [0, 0, 0], fov: FOV },
    settings: { background: [0, 0, 0], timeSamples },
    objects: [{ id: 'ball', shape: 'sphere', position: [START, 0, 0], velocity: [velocity, 0, 0], scale: [2 * RADIUS, 2 * RADIUS, 2 * RADIUS], material: matte([1, 1, 1], { ambient: 1, diffuse: 0 }) }],
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

describe('motion blur', () => {
  it('a still object covers only its own pixels', () => {
    const [first, last] = litRange(centreRow(0, 16));
    expect(Math.abs(first - column(START - RADIUS))).toBeLessThanOrEqual(1);
    expect(Math.abs(last - column(START + RADIUS))).toBeLessThanOrEqual(1);
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
});
