import { RAY_DASHES, type RayColorKey } from './ray-palette.ts';

/**
 * How a pixel's sample paths are drawn (path-tracing spec §5): the path itself — the camera
 * ray and every bounce — as solid lines, and the light-sampling rays (next-event estimation:
 * a shadow ray from a diffuse vertex to a point on a light) dashed, reached (yellow) or
 * blocked (grey, its gaps filled as in Whitted mode). A path is then read as one solid line
 * with dashed side-branches to the lights, and the two kinds never share a pattern. Bounce
 * types still differ by colour (reflected blue, refracted green) and by their arrowheads.
 */
export const PATH_DASHES: Readonly<Record<RayColorKey, readonly [dash: number, gap: number]>> = {
  ...RAY_DASHES,
  primary: [0, 0],
  reflect: [0, 0],
  refract: [0, 0],
  'no-hit': [0, 0],
  light: [0.06, 0.04],
  shadow: [0.06, 0.04],
};
