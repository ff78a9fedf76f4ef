/**
 * The refraction lab's named edge cases, each a misconception the random cases may not name
 * (spec/code-labs.md §1). A file of its own so that the level schema can list them without
 * loading the grader.
 */
export const REFRACTION_EDGES = ['into-glass-slanted', 'into-glass-straight', 'out-of-glass-slanted', 'total-internal-reflection', 'into-diamond'] as const;
export type RefractionEdge = (typeof REFRACTION_EDGES)[number];
