import { Euler, Quaternion } from 'three';
import type { Vec3 } from '../scene/scene.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';

/**
 * The scene file's rotation convention, in one place: a rotation is [x, y, z] in degrees,
 * applied in three.js's Euler order 'XYZ' (an Object3D's own). The tracer builds its shapes'
 * and lights' rotations here and the 3D view its meshes' and gizmos', so what is drawn is
 * what is traced.
 */
export const SCENE_EULER_ORDER = 'XYZ';

/** A scene rotation as an Euler, written into `out` (an Object3D's `rotation` will do). */
export function sceneEuler(rotation: Vec3, out: Euler = new Euler()): Euler {
  return out.set(rotation[0] * RADIANS_PER_DEGREE, rotation[1] * RADIANS_PER_DEGREE, rotation[2] * RADIANS_PER_DEGREE, SCENE_EULER_ORDER);
}

/** A scene rotation as a quaternion, written into `out`. */
export function sceneQuaternion(rotation: Vec3, out: Quaternion = new Quaternion()): Quaternion {
  return out.setFromEuler(sceneEuler(rotation));
}
