/**
 * The Phong lab's named edge cases, each a misconception the random cases may not name
 * (spec/code-labs.md §1). A file of its own so that the level schema can list them without
 * loading the grader.
 */
export const PHONG_EDGES = ['phong-light-behind', 'phong-in-the-highlight', 'phong-beside-the-highlight', 'phong-coloured-light'] as const;
export type PhongEdge = (typeof PHONG_EDGES)[number];
