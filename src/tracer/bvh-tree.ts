import type { MeshBVH } from 'three-mesh-bvh';

/** One node of a model's BVH: its box in the model's own space, and either two children or a run of triangles. */
export interface BvhNode {
  /** min x, y, z then max x, y, z (the float32 values the BVH itself tests). */
  readonly bounds: Float32Array;
  readonly depth: number;
  /** For a leaf: its triangles are `offset` … `offset + count − 1` in the BVH's order. */
  readonly offset: number;
  readonly count: number;
  /** For an inner node: the axis (0 x, 1 y, 2 z) its children were split along, and the children. */
  readonly splitAxis: number;
  readonly left: BvhNode | null;
  readonly right: BvhNode | null;
}

/** A model's BVH as plain nodes: the root, how deep the deepest leaf is, and how many triangles there are. */
export interface BvhTree {
  readonly root: BvhNode;
  readonly maxDepth: number;
  readonly triangles: number;
}

const trees = new WeakMap<MeshBVH, BvhTree>();

/**
 * The nodes of a built three-mesh-bvh BVH, read once through its public `traverse` (which
 * visits depth first, left child before right) and kept: the BVH view draws them and the
 * test counter walks them, so both show exactly the tree the tracer casts through.
 */
export function bvhTree(bvh: MeshBVH): BvhTree {
  let tree = trees.get(bvh);
  if (tree) return tree;
  type Building = { -readonly [K in keyof BvhNode]: BvhNode[K] };
  const path: Building[] = [];
  let root: Building | null = null;
  let maxDepth = 0;
  let triangles = 0;
  bvh.traverse((depth, isLeaf, boundingData, offsetOrSplit, count) => {
    const node: Building = {
      bounds: Float32Array.from(boundingData.subarray(0, 6)),
      depth,
      offset: isLeaf ? offsetOrSplit : 0,
      count: isLeaf ? count : 0,
      splitAxis: isLeaf ? -1 : offsetOrSplit,
      left: null,
      right: null,
    };
    path.length = depth;
    const parent = path[depth - 1];
    if (parent) {
      if (parent.left) parent.right = node;
      else parent.left = node;
    } else {
      root = node;
    }
    path.push(node);
    maxDepth = Math.max(maxDepth, depth);
    if (isLeaf) triangles += count;
  });
  if (!root) throw new Error('the BVH has no nodes');
  tree = { root, maxDepth, triangles };
  trees.set(bvh, tree);
  return tree;
}

/** The nodes at `depth`, and the leaves above it (a branch that ends early): together they cover the model. */
export function nodesAtDepth(tree: BvhTree, depth: number): BvhNode[] {
  const found: BvhNode[] = [];
  const visit = (node: BvhNode) => {
    if (node.depth === depth || !node.left || !node.right) found.push(node);
    else {
      visit(node.left);
      visit(node.right);
    }
  };
  visit(tree.root);
  return found;
}
