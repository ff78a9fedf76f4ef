import { describe, expect, it } from 'vitest';
import type { Intersectable } from '../../src/tracer/intersectable.ts';
import { WalkStarts } from '../../src/tracer/walk-starts.ts';

/**
 * A tree of 4 leaves, depth first as ObjectBvh stores it (a node's left child follows it, link
 * holds the right one):
 *   0 ─┬─ 1 ─┬─ 2 (a, b)
 *      │     └─ 3 (c)
 *      └─ 4 ─┬─ 5 (d)
 *            └─ 6 (e, f)
 */
const link = Int32Array.from([4, 3, 0, 2, 6, 3, 4]);
const count = Int32Array.from([0, 0, 2, 1, 0, 1, 2]);
const items = ['a', 'b', 'c', 'd', 'e', 'f'].map((id) => ({ id }) as Intersectable);
const [a, b, c, d, e, f] = items;

describe('the start of an object BVH walk', () => {
  const starts = new WalkStarts(link, count, items);
  const stack = new Int32Array(16);
  const startOf = (object: Intersectable | null) => Array.from(stack.subarray(0, starts.fill(stack, object)));

  it('is the root for a query that starts nowhere in particular', () => {
    expect(startOf(null)).toEqual([0]);
  });

  it('is the object’s leaf on top of its ancestors’ siblings, lowest nearest the top', () => {
    // Popped from the end: the leaf, then its sibling, then its parent's sibling.
    expect(startOf(a)).toEqual([4, 3, 2]);
    expect(startOf(b)).toEqual([4, 3, 2]);
    expect(startOf(c)).toEqual([4, 2, 3]);
    expect(startOf(d)).toEqual([1, 6, 5]);
    expect(startOf(f)).toEqual([1, 5, 6]);
    // Asked again after another object: not the last answer kept.
    expect(startOf(e)).toEqual([1, 5, 6]);
    expect(startOf(c)).toEqual([4, 2, 3]);
  });

  it('covers every leaf exactly once, whichever object it starts from', () => {
    const leavesUnder = (node: number): number[] => (count[node] > 0 ? [node] : [...leavesUnder(node + 1), ...leavesUnder(link[node])]);
    for (const object of items) expect(startOf(object).flatMap(leavesUnder).sort()).toEqual([2, 3, 5, 6]);
  });

  it('is the root for an object not in the tree, and for a tree that is one leaf', () => {
    expect(startOf({ id: 'elsewhere' } as Intersectable)).toEqual([0]);
    const oneLeaf = new WalkStarts(Int32Array.from([0]), Int32Array.from([3]), [a, b, c]);
    expect(Array.from(stack.subarray(0, oneLeaf.fill(stack, b)))).toEqual([0]);
  });
});
