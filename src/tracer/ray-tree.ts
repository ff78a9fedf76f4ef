import type { Color, Vec3 } from '../scene/scene.ts';
import type { ShadingTerms } from './shading-terms.ts';

/** The ray kinds of spec §3, in the order of VRT's legend. */
export type RayType = 'primary' | 'reflect' | 'refract' | 'shadow' | 'light' | 'area-light' | 'area-shadow';

/** One ray of a pixel's ray tree (spec §3). */
export interface RayNode {
  type: RayType;
  origin: Vec3;
  /** Unit direction. */
  direction: Vec3;
  /** Distance to the hit, to the light, or 10 for a ray that hit nothing. */
  length: number;
  hit: boolean;
  objectId: string | null;
  lightId: string | null;
  /** What the ray carries back to its parent (for a light ray: that light's term). */
  color: Color;
  /** The ray's share of the pixel colour, 0..1. */
  contribution: number;
  children: RayNode[];
  /** area-light / area-shadow only: the light's four corners (the cone's base). */
  corners?: [Vec3, Vec3, Vec3, Vec3];
  /**
   * Lens or time rays only (a `primary` child of a root, when a pixel sample casts more than
   * one ray: distribution-effects §3): where on the lens it starts (its origin).
   */
  lensPoint?: Vec3;
  /** Lens or time rays only: τ in [0, 1), when in the open shutter the ray (and its tree) is cast. */
  time?: number;
  /** reflect / refract rays spread around the ideal direction by a rough material. */
  glossy?: true;
  /** A glossy direction pointing into the surface: not traced, it adds black (length 0). */
  absorbed?: true;
  /**
   * A primary, reflected or refracted ray that hit a surface: the unit surface normal N at its
   * hit point (origin + length · direction), turned toward the ray as the shading used it
   * (spec §2; for a ray inside glass it points inward). The lab draws it at the hit.
   */
  normal?: Vec3;
  /**
   * A light or area-light ray recorded with `settings.shadows` off: no shadow ray was cast, so
   * nothing was tested on the way and the light counts as reaching the point (S = 1). The
   * node is the direction to the light, which the lab draws as "not tested".
   */
  untested?: true;
  /** A ray that hit a surface, traced with terms (`rt trace --terms`): the parts of its colour. */
  terms?: ShadingTerms;
  /**
   * Traced with terms: what this ray's colour is multiplied by where it is added: 1/s² for a
   * root (into the pixel), 1/(n²·k) for a lens or time ray (into its root), ks, kr or kt for
   * a reflected or refracted ray (over m² for a glossy one). Light rays have none: their
   * colour is what they add.
   */
  weight?: number;
  /**
   * A light or shadow ray traced with terms: its sample's diffuse and highlight (its colour is
   * their sum; 0 when blocked), so a debugger can grow a light's terms sample by sample.
   */
  parts?: { diffuse: Color; specular: Color };
}

/** The answer to "which rays made this pixel?" (`rt trace`). */
export interface PixelTrace {
  pixel: [number, number];
  color: Color;
  /** One root per supersample (s² roots). */
  rays: RayNode[];
  /** Rays traced for the pixel, when a budget sent fewer of them in `rays` (tree-budget.ts). */
  traced?: number;
  /**
   * The one supersample traced, when the lab traced a heavy screen's pixel from it alone while
   * the learner edits (trace-within-budget.ts): the colour is that sample's and `rays` some of
   * its trees; the rays of the other samples were neither traced nor counted.
   */
  onlySample?: number;
}

/** Ray counts by kind, for `rt render --stats` and the benchmark. */
export interface RayStats {
  primary: number;
  shadow: number;
  reflect: number;
  refract: number;
}

export function emptyRayStats(): RayStats {
  return { primary: 0, shadow: 0, reflect: 0, refract: 0 };
}

export function addRayStats(into: RayStats, from: RayStats): void {
  into.primary += from.primary;
  into.shadow += from.shadow;
  into.reflect += from.reflect;
  into.refract += from.refract;
}
