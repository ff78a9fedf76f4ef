/**
 * The normals the cosine-bounce lab runs the learner's function with, by name (the lab's kinds
 * of case, in the level files and the classroom's logs): along +z, where a function without a
 * frame around the normal is right; −z and +y, where it is not; and one along no axis. Kept
 * apart from the lab so that the level schema does not load the tracer.
 */
export const COSINE_NORMALS = ['normal-plus-z', 'normal-minus-z', 'normal-plus-y', 'normal-slanted'] as const;
export type CosineNormal = (typeof COSINE_NORMALS)[number];
