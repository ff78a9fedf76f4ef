/**
 * The shadow-test lab's named edge cases, each a misconception the random cases may not hit
 * (spec/code-labs.md §1): a sphere between the point and the light, none in the way, one
 * beyond the light (it cannot block light that never reaches it), one behind the point
 * (t < 0), the point's own sphere (the shadow ray starts just off its surface and leaves it),
 * and several spheres where only the last in the list blocks. A file of its own so that the
 * level schema can list them without loading the grader (and the tracer).
 */
export const SHADOW_EDGES = ['blocked', 'nothing-in-the-way', 'beyond-the-light', 'behind-the-point', 'own-sphere', 'several-spheres'] as const;
export type ShadowEdge = (typeof SHADOW_EDGES)[number];
