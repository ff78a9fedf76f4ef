/**
 * The ray–sphere lab's named edge cases, each a misconception the random cases may not hit
 * (spec/code-labs.md §1). A file of its own so that the level schema can list them without
 * loading the grader (and the tracer) with the first screen.
 */
export const RAY_SPHERE_EDGES = ['hit-from-outside', 'miss', 'sphere-behind', 'inside-sphere', 'tangent', 'off-centre'] as const;
export type RaySphereEdge = (typeof RAY_SPHERE_EDGES)[number];
