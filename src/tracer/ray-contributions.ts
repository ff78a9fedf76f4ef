import type { RayNode } from './ray-tree.ts';

/**
 * Fills in each ray's share of the pixel (spec §3): roots get 1/s² (`rootShare`, when only
 * some of the s² roots are recorded: trace-within-budget.ts); a child gets
 * parent.contribution × (what the parent adds from it) / (the parent's colour), summed
 * over the channels, and 0 when the parent is black. `weights` holds what the parent
 * multiplies the child's colour by (ks, kr or kt; light rays are added as they are).
 * Example: a ray with 25% whose children give 40% and 20% of its colour has children of
 * 10% and 5%.
 *
 * The parent's colour is taken before clamping (`unclampedSums`, per recorded hit): a hit
 * brighter than white is clamped to 1 per channel, yet its children add up to its unclamped
 * colour, so dividing by the clamped one gave the children together more than their
 * parent's share (shares over 100 % in the ray panel). Over the unclamped sum, the
 * children's shares add up to at most the parent's; the rest is the hit's own ambient term.
 */
export function assignContributions(
  roots: RayNode[],
  weights: ReadonlyMap<RayNode, number>,
  unclampedSums: ReadonlyMap<RayNode, number> = new Map(),
  rootShare = 1 / roots.length,
): void {
  for (const root of roots) assign(root, rootShare, weights, unclampedSums);
}

function assign(node: RayNode, contribution: number, weights: ReadonlyMap<RayNode, number>, unclampedSums: ReadonlyMap<RayNode, number>): void {
  node.contribution = contribution;
  const parentSum = unclampedSums.get(node) ?? sum(node.color);
  for (const child of node.children) {
    const added = (weights.get(child) ?? 1) * sum(child.color);
    assign(child, parentSum > 0 ? (contribution * added) / parentSum : 0, weights, unclampedSums);
  }
}

function sum(color: readonly number[]): number {
  return color[0] + color[1] + color[2];
}
