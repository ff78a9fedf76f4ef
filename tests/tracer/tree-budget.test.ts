import { describe, expect, it } from 'vitest';
import type { PixelTrace, RayNode } from '../../src/tracer/ray-tree.ts';
import { type BudgetTrees, keptTrees, thinTraces, tracedRays } from '../../src/tracer/tree-budget.ts';
import { countNodes, ray } from '../support/ray-fixtures.ts';

/** Trees of the given sizes, one pixel each unless `pixels` says otherwise, all of kind 0 unless `kinds` says. */
function trees(sizes: number[], options: { pixels?: number[]; kinds?: number[][]; parents?: number[] } = {}): BudgetTrees {
  return {
    count: sizes.length,
    kindCount: 8,
    size: (t) => sizes[t],
    pixel: (t) => options.pixels?.[t] ?? t,
    parent: (t) => options.parents?.[t] ?? -1,
    kinds: (t, visit) => (options.kinds?.[t] ?? [0]).forEach(visit),
  };
}

const kept = (keep: Uint8Array) => [...keep.keys()].filter((t) => keep[t] === 1);
const keptRays = (sizes: number[], keep: Uint8Array) => kept(keep).reduce((sum, t) => sum + sizes[t], 0);

describe('keptTrees: which ray trees a budget keeps', () => {
  it('keeps every tree when all of them fit', () => {
    expect(kept(keptTrees(trees([3, 3, 4]), 10, null))).toEqual([0, 1, 2]);
  });

  it('keeps about the budget, spread evenly over the screen', () => {
    const sizes = Array(100).fill(5);
    const keep = keptTrees(trees(sizes), 100, null);
    expect(keptRays(sizes, keep)).toBe(100);
    // Every fifth tree: no run of the screen is left bare.
    const gaps = kept(keep)
      .slice(1)
      .map((t, i) => t - kept(keep)[i]);
    expect(Math.max(...gaps)).toBe(5);
    expect(Math.min(...gaps)).toBe(5);
  });

  it('keeps every tree of the chosen pixel, counted in the budget', () => {
    const sizes = Array(40).fill(5);
    const pixels = sizes.map((_, t) => Math.floor(t / 4)); // 10 pixels of 4 trees
    const keep = keptTrees(trees(sizes, { pixels }), 40, 7);
    expect(kept(keep).filter((t) => pixels[t] === 7)).toEqual([28, 29, 30, 31]);
    expect(keptRays(sizes, keep)).toBe(40);
    // Even when the pixel alone is over the budget.
    expect(kept(keptTrees(trees(sizes, { pixels }), 10, 7))).toEqual([28, 29, 30, 31]);
  });

  it('keeps a tree of every kind there is, the first that has it', () => {
    const sizes = Array(50).fill(4);
    // The budget alone keeps every tenth tree (4, 14, 24, …): none of the two with kind 5.
    const kinds = sizes.map((_, t) => (t === 33 || t === 43 ? [0, 5] : [0]));
    expect(kept(keptTrees(trees(sizes), 20, null))).toEqual([4, 14, 24, 34, 44]);
    const keep = keptTrees(trees(sizes, { kinds }), 20, null);
    expect(kept(keep)).toEqual([4, 14, 24, 33, 34, 44]);
  });

  it('keeps the parent of a tree it keeps, and pays for it with the first child kept', () => {
    // Two samples, each a pinhole ray (1 ray) with 10 lens rays of 3 rays each below it.
    const sizes = [1, ...Array(10).fill(3), 1, ...Array(10).fill(3)];
    const parents = sizes.map((_, t) => (t === 0 || t === 11 ? -1 : t < 11 ? 0 : 11));
    const keep = keptTrees(trees(sizes, { parents, pixels: sizes.map(() => 0) }), 14, null);
    for (const t of kept(keep)) if (parents[t] >= 0) expect(keep[parents[t]]).toBe(1);
    expect(keep[0] + keep[11]).toBe(2);
    expect(keptRays(sizes, keep)).toBeLessThanOrEqual(14 + 3);
  });

  it('is deterministic: the same trees and budget keep the same trees', () => {
    const sizes = Array.from({ length: 300 }, (_, t) => 1 + ((t * 7) % 11));
    const kinds = sizes.map((_, t) => [t % 3, (t * 5) % 7]);
    expect([...keptTrees(trees(sizes, { kinds }), 250, 4)]).toEqual([...keptTrees(trees(sizes, { kinds }), 250, 4)]);
  });
});

/** A pixel sample that casts `lensRays` rays (a lens), each with a light ray below it; the root is the pinhole ray. */
function lensSample(lensRays: number, kindOfLast: RayNode['type'] = 'light'): RayNode {
  return ray('primary', {
    children: Array.from({ length: lensRays }, (_, i) =>
      ray('primary', { time: 0, lensPoint: [i, 0, 0], children: [ray(i === lensRays - 1 ? kindOfLast : 'light')] }),
    ),
  });
}

const pixel = (x: number, roots: RayNode[]): PixelTrace => ({ pixel: [x, 0], color: [0.1, 0.2, 0.3], rays: roots });

describe('thinTraces: a block of pixels sent with a budget', () => {
  it('sends every tree untouched when they fit', () => {
    const traces = [pixel(0, [ray('primary', { children: [ray('light')] })])];
    const sent = thinTraces(traces, 10, null);
    expect(sent).toEqual(traces);
    expect(sent[0].traced).toBeUndefined();
  });

  it('keeps lens rays with their pinhole ray, says how many each pixel had, and leaves the traces it was given alone', () => {
    const traces = [0, 1, 2, 3].map((x) => pixel(x, [lensSample(8), lensSample(8)]));
    const before = structuredClone(traces);
    const sent = thinTraces(traces, 40, null);
    expect(traces).toEqual(before);
    const total = tracedRays(sent);
    expect(total).toBe(4 * 2 * (1 + 8 * 2));
    const kept = sent.reduce((sum, trace) => sum + countNodes(trace.rays), 0);
    expect(kept).toBeGreaterThan(20);
    expect(kept).toBeLessThanOrEqual(40 + 3);
    for (const trace of sent) {
      expect(trace.traced).toBe(2 * (1 + 8 * 2));
      // Every kept lens ray hangs under its sample's pinhole ray with its own light ray.
      for (const root of trace.rays) for (const lens of root.children) expect(lens.children).toHaveLength(1);
      expect(trace.color).toEqual([0.1, 0.2, 0.3]);
    }
    expect(sent.every((trace) => trace.rays.length > 0)).toBe(true);
  });

  it('keeps every ray of the chosen pixel and the one refraction among them', () => {
    const traces = [0, 1, 2, 3, 4, 5].map((x) => pixel(x, [lensSample(6, x === 5 ? 'refract' : 'light')]));
    const sent = thinTraces(traces, 12, 2);
    expect(sent[2].rays).toEqual(traces[2].rays);
    expect(sent[2].traced).toBeUndefined();
    const refractions = sent
      .flatMap((trace) => trace.rays.flatMap((root) => root.children.flatMap((lens) => lens.children)))
      .filter((node) => node.type === 'refract');
    expect(refractions).toHaveLength(1);
  });
});
