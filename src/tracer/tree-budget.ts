import type { PixelTrace, RayNode, RayType } from './ray-tree.ts';

/**
 * Which ray trees a budget of rays keeps, when a screen has more rays than can be shown while
 * the learner edits (the lab's 3D view on a CPU rasterizer: view/ray-budget.ts). The same
 * rule thins the trees a worker sends (`thinTraces`) and the rays the view draws.
 *
 * A tree is a ray from the camera with every ray it caused. A pixel sample that casts
 * several rays (lens points, shutter times) has the pinhole ray as its root and them as its
 * children (render-pixel.ts): the root alone is then one tree, the parent of each of theirs.
 *
 * - Nothing is left out when everything fits.
 * - Whole trees only, and a kept tree keeps its parent: no ray without the ray it came from.
 * - Every tree of the chosen pixel (`keepPixel`) is kept, out of the budget first.
 * - The trees kept are spread evenly over the screen, in screen order, by error diffusion (as
 *   in Floyd–Steinberg dithering): each tree adds its share of the budget to what is owed,
 *   and is kept when that reaches half its size, which is then paid back (with its parent's
 *   size, for the first of a parent's trees kept).
 * - Every kind of ray in the screen keeps at least one tree that shows it (the first), so a
 *   rare kind (one refraction, one blocked shadow ray) does not vanish.
 * - Deterministic: the same trees and budget keep the same trees, so a frame does not
 *   flicker between two thinnings of the same rays.
 */
export interface BudgetTrees {
  /** Trees in screen order. */
  readonly count: number;
  /** Kinds are numbered from 0 to kindCount − 1. */
  readonly kindCount: number;
  /** Rays in tree t. */
  size(t: number): number;
  /** The pixel of tree t (y · columns + x). */
  pixel(t: number): number;
  /** The tree whose ray tree t's first ray came from, or −1. */
  parent(t: number): number;
  /** Calls `visit` with the kind of each ray of tree t. */
  kinds(t: number, visit: (kind: number) => void): void;
}

/** Per tree, 1 when `budget` keeps it: the rule above. */
export function keptTrees(trees: BudgetTrees, budget: number, keepPixel: number | null): Uint8Array {
  const count = trees.count;
  const keep = new Uint8Array(count);
  const sizes = new Int32Array(count);
  let total = 0;
  let chosen = 0;
  for (let t = 0; t < count; t++) {
    total += sizes[t] = trees.size(t);
    if (trees.pixel(t) === keepPixel) {
      keep[t] = 1;
      chosen += sizes[t];
    }
  }
  if (total <= budget) return keep.fill(1);
  // The chosen pixel's rays come out of the budget first; the other trees share the rest.
  const share = Math.max(0, budget - chosen) / (total - chosen);
  let owed = 0;
  for (let t = 0; t < count; t++) {
    if (keep[t]) continue;
    owed += sizes[t] * share;
    // A tree with trees below it (a sample's pinhole ray) is kept with the first of them kept, and paid for then.
    if (t + 1 < count && trees.parent(t + 1) === t) continue;
    const parent = trees.parent(t);
    const cost = sizes[t] + (parent >= 0 && !keep[parent] ? sizes[parent] : 0);
    if (owed >= cost / 2) {
      keep[t] = 1;
      if (parent >= 0) keep[parent] = 1;
      owed -= cost;
    }
  }
  const firstWith = new Int32Array(trees.kindCount).fill(-1);
  const shown = new Uint8Array(trees.kindCount);
  for (let t = 0; t < count; t++) {
    trees.kinds(t, (kind) => {
      if (firstWith[kind] < 0) firstWith[kind] = t;
      if (keep[t]) shown[kind] = 1;
    });
  }
  firstWith.forEach((t, kind) => {
    if (t >= 0 && !shown[kind]) keep[t] = 1;
  });
  // Parents come before their children in screen order: one pass back to front reaches them all.
  for (let t = trees.count - 1; t >= 0; t--) if (keep[t] && trees.parent(t) >= 0) keep[trees.parent(t)] = 1;
  return keep;
}

/** Whether every pixel of `traces` was traced whole, so tracedRays counts all of their rays (PixelTrace.onlySample). */
export function countsEveryRay(traces: readonly PixelTrace[]): boolean {
  return traces.every((trace) => trace.onlySample === undefined);
}

/** Rays in the trees, with those a budget left out (PixelTrace.traced); a pixel traced from one sample counts only its rays sent. */
export function tracedRays(traces: readonly PixelTrace[]): number {
  let rays = 0;
  for (const trace of traces) rays += trace.traced ?? countRays(trace.rays);
  return rays;
}

/**
 * `traces` (pixels first, first + 1, … of the screen) thinned to about `budget` rays by the
 * rule above; a pixel that lost rays says how many it had (`traced`). `keepPixel` counts
 * from `first` too.
 */
export function thinTraces(traces: readonly PixelTrace[], budget: number, keepPixel: number | null): PixelTrace[] {
  const trees = rayTreesOf(traces);
  const keep = keptTrees(trees, budget, keepPixel);
  if (keep.every((kept) => kept === 1)) return [...traces];
  const thinned: PixelTrace[] = traces.map((trace) => ({ ...trace, rays: [] }));
  const traced = new Int32Array(traces.length);
  const sent = new Int32Array(traces.length);
  const copies: RayNode[] = [];
  for (let t = 0; t < trees.count; t++) {
    const p = trees.pixel(t);
    traced[p] += trees.size(t);
    if (!keep[t]) continue;
    sent[p] += trees.size(t);
    const node = trees.nodes[t];
    const parent = trees.parent(t);
    // A root with children of their own trees is copied, so that only its kept ones go in (the traces given stay as they were).
    copies[t] = trees.nested[t] ? { ...node, children: [] } : node;
    if (parent < 0) thinned[p].rays.push(copies[t]);
    else copies[parent].children.push(node);
  }
  thinned.forEach((trace, p) => {
    if (sent[p] < traced[p]) trace.traced = traced[p];
  });
  return thinned;
}

/** The trees of `traces` as the rule sees them; `pixel` counts from the first trace. */
function rayTreesOf(traces: readonly PixelTrace[]): BudgetTrees & { nodes: RayNode[]; nested: boolean[] } {
  const nodes: RayNode[] = [];
  const pixels: number[] = [];
  const parents: number[] = [];
  const nested: boolean[] = [];
  const sizes: number[] = [];
  /** Per tree, bit k set when it has a ray of kind k (there are fewer than 32). */
  const kinds: number[] = [];
  const add = (node: RayNode, p: number, parent: number, alone: boolean) => {
    nodes.push(node);
    pixels.push(p);
    parents.push(parent);
    nested.push(alone);
    let size = 0;
    let mask = 0;
    const stack = [node];
    while (stack.length > 0) {
      const ray = stack.pop()!;
      size++;
      mask |= 1 << kindOf(ray);
      if (!alone) for (const child of ray.children) stack.push(child);
    }
    sizes.push(size);
    kinds.push(mask);
  };
  traces.forEach((trace, p) => {
    for (const root of trace.rays) {
      const rootTree = nodes.length;
      const several = root.time === undefined && root.children.length > 0 && root.children[0].time !== undefined;
      add(root, p, -1, several);
      if (several) for (const child of root.children) add(child, p, rootTree, false);
    }
  });
  return {
    nodes,
    nested,
    count: nodes.length,
    kindCount: RAY_KIND_COUNT,
    size: (t) => sizes[t],
    pixel: (t) => pixels[t],
    parent: (t) => parents[t],
    kinds: (t, visit) => {
      for (let mask = kinds[t], kind = 0; mask !== 0; mask >>>= 1, kind++) if (mask & 1) visit(kind);
    },
  };
}

/** A ray's kind for the rule: its type, and whether it hit and was tested (the legend's entries follow from these). */
export function rayKind(type: RayType, hit: boolean, untested: boolean): number {
  return TYPE_INDEX[type] * 4 + (hit ? 2 : 0) + (untested ? 1 : 0);
}

function kindOf(node: RayNode): number {
  return rayKind(node.type, node.hit, node.untested === true);
}

const TYPE_INDEX: Readonly<Record<RayType, number>> = { primary: 0, reflect: 1, refract: 2, shadow: 3, light: 4, 'area-light': 5, 'area-shadow': 6 };

/** Kinds are numbered 0 … RAY_KIND_COUNT − 1 (rayKind). */
export const RAY_KIND_COUNT = Object.keys(TYPE_INDEX).length * 4;

function countRays(roots: readonly RayNode[]): number {
  let rays = 0;
  for (const node of roots) rays += 1 + countRays(node.children);
  return rays;
}
