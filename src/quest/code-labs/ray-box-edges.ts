/**
 * The AABB slab test lab's named edge cases, each a misconception the random cases may not
 * hit (spec/code-labs.md §1): rays parallel to a slab, inside it, outside it and exactly in a
 * face's plane (where 0 · ∞ is NaN), a box behind the origin, an origin inside the box, a
 * direction with negative components (the entry and exit planes swap) and a ray that just
 * touches an edge. A file of its own so that the level schema can list them without loading
 * the grader (and the tracer).
 */
export const RAY_BOX_EDGES = [
  'box-hit-from-outside',
  'box-miss',
  'box-behind',
  'inside-box',
  'negative-direction',
  'parallel-inside-slab',
  'parallel-outside-slab',
  'in-face-plane',
  'touches-edge',
] as const;
export type RayBoxEdge = (typeof RAY_BOX_EDGES)[number];
