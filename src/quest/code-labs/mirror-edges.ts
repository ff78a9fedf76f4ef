/**
 * The mirror lab's named edge cases, each a misconception the random cases may not name
 * (spec/code-labs.md §1). A file of its own so that the level schema can list them without
 * loading the grader.
 */
export const MIRROR_EDGES = ['mirror-slanted', 'mirror-head-on', 'mirror-grazing', 'mirror-tilted'] as const;
export type MirrorEdge = (typeof MIRROR_EDGES)[number];
