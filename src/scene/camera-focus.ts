import type { Camera, Vec3 } from './scene.ts';
import { LIMITS } from './scene-limits.ts';

/**
 * The focus distance that puts `point` on the plane in focus: its distance from the camera
 * along the view direction (the plane is perpendicular to it, distribution-effects §2),
 * kept within the schema's range (a point behind or at the eye gets the nearest plane).
 */
export function focusDistanceTo(camera: Pick<Camera, 'position' | 'target'>, point: Vec3): number {
  const view = camera.target.map((t, axis) => t - camera.position[axis]);
  const length = Math.hypot(...view);
  const along = view.reduce((sum, v, axis) => sum + (v / length) * (point[axis] - camera.position[axis]), 0);
  const [nearest, farthest] = LIMITS.focusDistance;
  return Math.min(farthest, Math.max(nearest, along));
}

/** The focus distance in use: the scene's, or (left out) the distance to the target. */
export function effectiveFocusDistance(camera: Pick<Camera, 'position' | 'target' | 'focusDistance'>): number {
  return camera.focusDistance ?? Math.hypot(...camera.target.map((t, axis) => t - camera.position[axis]));
}
