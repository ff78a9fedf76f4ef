import { describe, expect, it } from 'vitest';
import { owenScramble, pixelSamplePoint, reverseBits32, sobolPoint } from '../../src/tracer/sobol-pixel-samples.ts';
import { hashKey } from '../../src/tracer/sampler.ts';

/** The first n points of the pixel whose scrambling seeds are (su, sv). */
function points(n: number, su: number, sv: number): [number, number][] {
  return Array.from({ length: n }, (_, index) => [...pixelSamplePoint(index, su, sv, [0, 0])] as [number, number]);
}

/** True when every box 2^-a × 2^-b (a + b = m) of the unit square holds exactly one of the 2^m points. */
function isNet(pts: [number, number][], m: number): boolean {
  for (let a = 0; a <= m; a++) {
    const b = m - a;
    const counts = new Map<number, number>();
    for (const [u, v] of pts) {
      const box = Math.floor(u * 2 ** a) * 2 ** b + Math.floor(v * 2 ** b);
      counts.set(box, (counts.get(box) ?? 0) + 1);
    }
    if (counts.size !== 2 ** m || [...counts.values()].some((count) => count !== 1)) return false;
  }
  return true;
}

describe("path mode's stratified pixel points (Owen-scrambled Sobol)", () => {
  it('reverses bits and follows the Sobol sequence: (0,0), (½,½), (¼,¾), (¾,¼), …', () => {
    expect(reverseBits32(1)).toBe(0x80000000);
    expect(reverseBits32(0x80000000)).toBe(1);
    expect(reverseBits32(0x12345678)).toBe(0x1e6a2c48);
    const first = [0, 1, 2, 3].map((index) => sobolPoint(index, [0, 0]).map((bits) => bits / 2 ** 32));
    expect(first).toEqual([
      [0, 0],
      [0.5, 0.5],
      [0.25, 0.75],
      [0.75, 0.25],
    ]);
  });

  it('put one point in each elementary box for every power-of-two prefix, whatever the pixel', () => {
    for (const pixel of [0, 1, 2]) {
      const pts = points(256, hashKey(pixel, 1), hashKey(pixel, 2));
      for (let m = 0; m <= 8; m++) expect(isNet(pts.slice(0, 2 ** m), m), `pixel ${pixel}, ${2 ** m} points`).toBe(true);
    }
  });

  it('measure how much of a pixel an edge covers to within one point in 64', () => {
    // A straight vertical edge at u = c: 64 points, one in each column of width 1/64.
    const pts = points(64, hashKey(9, 1), hashKey(9, 2));
    for (const c of [0.1, 0.37, 0.5, 0.93]) {
      const covered = pts.filter(([u]) => u < c).length / 64;
      expect(Math.abs(covered - c)).toBeLessThanOrEqual(1 / 64);
    }
  });

  it('are each uniform over the pixel across scrambles, so the pixel mean stays unbiased', () => {
    // Point 5 of 4096 pixels: a 4 × 4 histogram with χ² of 15 degrees of freedom.
    const pixels = 4096;
    const counts = new Array<number>(16).fill(0);
    for (let pixel = 0; pixel < pixels; pixel++) {
      const [u, v] = pixelSamplePoint(5, hashKey(pixel, 1), hashKey(pixel, 2), [0, 0]);
      counts[Math.floor(u * 4) * 4 + Math.floor(v * 4)]!++;
    }
    const expected = pixels / 16;
    const chiSquared = counts.reduce((sum, count) => sum + (count - expected) ** 2 / expected, 0);
    expect(chiSquared).toBeLessThan(37.7); // the 0.1 % point of χ² with 15 degrees of freedom
  });

  it('scramble the leading digits by a permutation that the digits below them do not change', () => {
    const seen = new Set<number>();
    for (let v = 0; v < 4096; v++) seen.add(owenScramble(v << 20, 0x1234567) >>> 20);
    expect(seen.size).toBe(4096);
  });
});
