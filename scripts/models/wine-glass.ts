import { LatheGeometry, Path, type Vector2 } from 'three';
import type { ModelRecipe } from './model-recipe.ts';

/** Glass wall thickness of the bowl, in metres (at the model's 1 m scale). */
const WALL = 0.012;
const RIM_RADIUS = 0.2;
const RIM_HEIGHT = 1 - WALL / 2;

/**
 * The glass's cross-section (x = distance from the axis, y = height), walked once around
 * the solid glass so that the lathe makes a closed surface: out along the underside of
 * the foot, up the stem, up the outside of the bowl, over the rounded rim and down the
 * inside of the bowl back to the axis. Walking it this way round puts every normal on
 * the glass's outside (in the bowl, the outside of the glass is the air in the bowl).
 */
function profile(): Vector2[] {
  const path = new Path()
    .moveTo(0, 0)
    .lineTo(0.27, 0) // underside of the foot
    .absarc(0.27, 0.015, 0.015, -Math.PI / 2, Math.PI / 2, false) // rounded edge of the foot
    .quadraticCurveTo(0.07, 0.035, 0.032, 0.1) // top of the foot sweeping into the stem
    .quadraticCurveTo(0.02, 0.25, 0.034, 0.38) // the stem, slightly waisted
    .bezierCurveTo(0.14, 0.39, 0.33, 0.52, RIM_RADIUS + WALL / 2, RIM_HEIGHT) // outside of the bowl
    .absarc(RIM_RADIUS, RIM_HEIGHT, WALL / 2, 0, Math.PI, false) // the rim
    .bezierCurveTo(0.315, 0.54, 0.15, 0.425, 0, 0.425); // inside of the bowl, ending flat on the axis
  // Where one curve ends and the next begins, sines and cosines leave near-duplicate points;
  // a zero-length step would give the lathe a meaningless normal.
  return path.getPoints(10).filter((point, i, points) => i === 0 || point.distanceTo(points[i - 1]) > 1e-6);
}

/** A wine glass with a real wall: refraction through it enters and leaves the glass. */
export const wineGlass: ModelRecipe = {
  name: 'wine-glass',
  description: 'a wine glass (foot, stem and tulip bowl with a glass wall about 1 cm thick, one closed lathe surface), smooth normals',
  build: () => new LatheGeometry(profile(), 40),
};
