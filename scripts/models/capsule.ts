import { CapsuleGeometry } from 'three';
import type { ModelRecipe } from './model-recipe.ts';

const RADIUS = 0.25;
const TOTAL_HEIGHT = 1;

/** A smooth pill: three's CapsuleGeometry, a cylinder with hemispherical ends. */
export const capsule: ModelRecipe = {
  name: 'capsule',
  description: 'a capsule (pill) of radius 0.25 m along Y, smooth normals',
  // 12 cap rings and 32 sides keep the silhouette round in a 512-pixel render.
  build: () => new CapsuleGeometry(RADIUS, TOTAL_HEIGHT - 2 * RADIUS, 12, 32, 1),
};
