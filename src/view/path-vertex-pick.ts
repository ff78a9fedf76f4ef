import type { RayNode } from '../tracer/ray-tree.ts';
import type { PathTrees } from './path-focus.ts';

/** A vertex of one of a pixel's drawn paths. */
export interface PathVertexChoice {
  path: number;
  vertex: number;
}

/**
 * Which path vertex a click on a drawn path ray chooses (issue 42: the sampling lobe at a
 * vertex the learner picks in the 3D view). A vertex is where two segments meet, so a click
 * on a segment takes the nearer of its two ends; a dashed light-sampling ray belongs to the
 * vertex it was taken at. `along` is how far from the ray's origin the pointer passed it
 * (RayHover.along, ray-pool.ts). Null for a ray that is not one of these paths'.
 */
export function pathVertexOfRay(trees: PathTrees, node: RayNode, along: number): PathVertexChoice | null {
  for (let path = 0; path < trees.segments.length; path++) {
    const segment = trees.segments[path].indexOf(node);
    if (segment >= 0) return { path, vertex: along > node.length / 2 ? segment + 1 : segment };
    const vertex = trees.lights[path].findIndex((rays) => rays.includes(node));
    if (vertex >= 0) return { path, vertex };
  }
  return null;
}
