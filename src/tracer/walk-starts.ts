import type { Intersectable } from './intersectable.ts';

/**
 * Where a walk of the object BVH starts when its query starts on one of the objects: a ray
 * reflected, refracted or cast toward a light from a hit, or the shadow candidates of a
 * patch of hits. The walk from the root would test the box of every ancestor of that
 * object's leaf, and those boxes hold the start point, so the tests pass and only cost
 * (about seven on the 256-object benchmark grid). Started instead on a stack holding the
 * leaf on top, then the sibling of each of its ancestors from the lowest up, the walk
 * visits the same nodes but those ancestors, nearest first: the leaf and each sibling's
 * subtree together hold every object once, so nothing is missed whatever the start point.
 */
export class WalkStarts {
  /** Each object's stack in `stacks`: its offset (how many nodes, then the nodes bottom first). */
  private readonly stackOf = new Map<Intersectable, number>();
  private readonly stacks: Int32Array;
  /** The last object asked for and its offset: neighbouring hits are mostly on one object. */
  private lastObject: Intersectable | null = null;
  private lastAt = -1;
  /** A tree that is one leaf (up to a dozen objects) starts at its root whatever the object. */
  private readonly rootOnly: boolean;

  /**
   * @param link per node: an inner node's right child (its left child follows it), a leaf's first item
   * @param count per node: a leaf's number of items, 0 for an inner node
   */
  constructor(link: Int32Array, count: Int32Array, items: readonly Intersectable[]) {
    this.rootOnly = items.length === 0 || count[0] > 0;
    const stacks: number[] = [];
    const visit = (node: number, siblings: number[]): void => {
      if (count[node] > 0) {
        for (let i = link[node]; i < link[node] + count[node]; i++) this.stackOf.set(items[i], stacks.length);
        stacks.push(siblings.length + 1, ...siblings, node);
        return;
      }
      visit(node + 1, [...siblings, link[node]]);
      visit(link[node], [...siblings, node + 1]);
    };
    if (!this.rootOnly) visit(0, []);
    this.stacks = Int32Array.from(stacks);
  }

  /** Fills `stack` with the start of a walk for a query starting on `object` (null: anywhere); returns its size. */
  fill(stack: Int32Array, object: Intersectable | null): number {
    let at = -1;
    if (object !== null && !this.rootOnly) {
      if (object !== this.lastObject) {
        this.lastObject = object;
        this.lastAt = this.stackOf.get(object) ?? -1;
      }
      at = this.lastAt;
    }
    if (at < 0) {
      stack[0] = 0;
      return 1;
    }
    const stacks = this.stacks;
    const size = stacks[at];
    for (let k = 0; k < size; k++) stack[k] = stacks[at + 1 + k];
    return size;
  }
}
