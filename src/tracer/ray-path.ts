import type { PixelTrace, RayNode, RayType } from './ray-tree.ts';

/**
 * A ray of a pixel's tree named by the kinds of ray on the way to it from the camera, joined
 * by "/": "primary" is the camera's ray, "primary/shadow" the shadow ray from where it hits,
 * "primary/refract/reflect" the ray reflected inside the glass it went into. Each step is
 * the first child of that kind (a hit casts at most one reflected and one refracted ray; of
 * its shadow rays, the first light's). Levels use it to declare which rays a task's text
 * names (docs/levels.md, "Evidence").
 */
export type RayPath = string;

/** The kinds a path's steps may name: every ray type. */
export const RAY_PATH_KINDS: readonly RayType[] = ['primary', 'reflect', 'refract', 'shadow', 'light', 'area-light', 'area-shadow'];

/** A path: "primary", then any kinds, each after a "/". */
export const RAY_PATH_PATTERN = new RegExp(`^primary(/(${RAY_PATH_KINDS.join('|')}))*$`);

/**
 * The ray `path` names in `trace` (in its first sample, when the pixel has several), or null
 * when the tree has no such ray. A lens or time sample's own primary ray is a "primary"
 * child of its root, so "primary/primary/…" follows the first of them.
 */
export function followRayPath(trace: PixelTrace, path: RayPath): RayNode | null {
  const [first, ...rest] = path.split('/');
  let node = trace.rays[0]?.type === first ? trace.rays[0] : undefined;
  for (const kind of rest) node = node?.children.find((child) => child.type === kind);
  return node ?? null;
}
