import { v } from '../lab-vectors.ts';
import type { LabCamera } from './lab-camera.ts';
import type { LabRenderScene } from './lab-render-scene.ts';

/** Room left around the framed shapes, as a share of the picture's width or depth. */
const MARGIN = 0.15;

/** Straight down: x and z exactly 0, so every ray is parallel to the x slab and the z slab of every box along the axes. */
const DOWN = v(0, -1, 0);

/**
 * An orthographic view of the scene from straight above, every ray going straight down (Shirley
 * & Marschner, "Fundamentals of Computer Graphics", 4th ed., §4.3.1: parallel rays from a grid
 * of origins). The level's own camera is a pinhole: none of its rays has a component exactly
 * 0, so a slab test that mishandles a ray parallel to a slab (0 · ∞, or "parallel: always a
 * miss/always a hit") renders that view like a correct one. Here every ray has two zero
 * components, so such a test shows on every box.
 *
 * It frames the spheres and boxes the labs' functions meet, x to the right and −z (away from
 * the level's usual camera) up, the picture's aspect kept; the rays start above the highest of
 * them, so no ray starts inside one.
 */
export function topDownCamera(scene: LabRenderScene): LabCamera {
  const shapes = [
    ...scene.spheres.map(({ center, radius }) => ({
      min: v(center.x - radius, center.y - radius, center.z - radius),
      max: v(center.x + radius, center.y + radius, center.z + radius),
    })),
    ...scene.boxes,
  ];
  const lowest = (axis: 'x' | 'y' | 'z') => Math.min(...shapes.map(({ min }) => min[axis]));
  const highest = (axis: 'x' | 'y' | 'z') => Math.max(...shapes.map(({ max }) => max[axis]));
  const [left, right, far, near] = shapes.length > 0 ? [lowest('x'), highest('x'), lowest('z'), highest('z')] : [-1, 1, -1, 1];
  const top = shapes.length > 0 ? highest('y') + 1 : 1;
  const centreX = (left + right) / 2;
  const centreZ = (far + near) / 2;
  return (x, y, width, height) => {
    // The picture's width and depth in metres: the framed shapes plus the margin, widened along one axis to the picture's aspect.
    const across = Math.max((right - left) * (1 + 2 * MARGIN), ((near - far) * (1 + 2 * MARGIN) * width) / height, 1e-3);
    const deep = (across * height) / width;
    return { origin: v(centreX + (x / width - 0.5) * across, top, centreZ + (y / height - 0.5) * deep), direction: DOWN };
  };
}
