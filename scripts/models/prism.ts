import { BufferGeometry, Float32BufferAttribute } from 'three';
import type { ModelRecipe } from './model-recipe.ts';

const HEIGHT = 1;
const SIDE = HEIGHT / (Math.sqrt(3) / 2); // equilateral: height = side · √3/2
const DEPTH = 1;

/**
 * A glass prism for the refraction lesson: an equilateral triangle (apex up) facing the
 * default camera along Z, extruded 1 m deep. Its faces are flat, so every corner is
 * written once per face with that face's normal: a smooth normal would bend the rays.
 */
export const prism: ModelRecipe = {
  name: 'prism',
  description: 'a triangular glass prism (equilateral cross-section in XY, apex up, 1 m deep along Z), flat faces',
  build() {
    const corners = [
      [-SIDE / 2, 0, DEPTH / 2],
      [SIDE / 2, 0, DEPTH / 2],
      [0, HEIGHT, DEPTH / 2], // front: 0 left, 1 right, 2 apex
      [-SIDE / 2, 0, -DEPTH / 2],
      [SIDE / 2, 0, -DEPTH / 2],
      [0, HEIGHT, -DEPTH / 2], // back: 3, 4, 5
    ];
    const triangles = [
      [0, 1, 2],
      [3, 5, 4], // front and back caps
      [0, 3, 4],
      [0, 4, 1], // floor
      [1, 4, 5],
      [1, 5, 2], // right slope
      [2, 5, 3],
      [2, 3, 0], // left slope
    ];
    const geometry = new BufferGeometry();
    geometry.setAttribute(
      'position',
      new Float32BufferAttribute(
        triangles.flat().flatMap((corner) => corners[corner]),
        3,
      ),
    );
    // Non-indexed, so each face's normal is its own.
    geometry.computeVertexNormals();
    return geometry;
  },
};
