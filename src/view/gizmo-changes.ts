import { Euler, type Quaternion, Vector3 } from 'three';
import { LIMITS } from '../scene/scene-limits.ts';
import type { Camera, Light, SceneObject, Vec3 } from '../scene/scene.ts';
import { SCENE_EULER_ORDER } from '../tracer/scene-rotation.ts';
import { DEGREES_PER_RADIAN } from '../util/angles.ts';

/** What Shift (or the Snap toggle) rounds a gizmo drag to: 0.25 m, 15°, 0.25× (as the lab's snapping did). */
export const SNAP = { translate: 0.25, rotateDegrees: 15, scale: 0.25 } as const;

/**
 * Without snapping, values are still rounded to steps far below what a student can see
 * (0.1 mm, 0.01°), so the panels show 1.25 rather than 1.2500000000000002.
 */
const FINE = { translate: 1e-4, rotateDegrees: 1e-2, scale: 1e-4 } as const;

/** The pose a gizmo drag left an object in (three.js's rotation is in radians). */
export interface DraggedPose {
  position: Vector3;
  quaternion: Quaternion;
  scale: Vector3;
}

/** `value` rounded to a multiple of `step`, printed cleanly (no 0.30000000000000004, no −0). */
export function roundToStep(value: number, step: number): number {
  const decimals = Math.max(0, Math.ceil(-Math.log10(step)) + 2);
  const rounded = Number((Math.round(value / step) * step).toFixed(decimals));
  return rounded === 0 ? 0 : rounded;
}

/** The scene's rotation (scene-rotation.ts) in degrees in (−180, 180], rounded, as the scene file stores it. */
export function eulerDegrees(quaternion: Quaternion, snap: boolean): Vec3 {
  euler.setFromQuaternion(quaternion, SCENE_EULER_ORDER);
  const step = snap ? SNAP.rotateDegrees : FINE.rotateDegrees;
  return [euler.x, euler.y, euler.z].map((radians) => {
    const degrees = roundToStep(radians * DEGREES_PER_RADIAN, step);
    return degrees <= -180 ? degrees + 360 : degrees;
  }) as Vec3;
}

function position(pose: DraggedPose, snap: boolean): Vec3 {
  const step = snap ? SNAP.translate : FINE.translate;
  return [roundToStep(pose.position.x, step), roundToStep(pose.position.y, step), roundToStep(pose.position.z, step)];
}

/** A scale factor rounded, and kept positive: the scene refuses zero and negative scales. */
function scaleFactor(value: number, snap: boolean): number {
  const step = snap ? SNAP.scale : FINE.scale;
  return Math.max(snap ? SNAP.scale : LIMITS.scale[0], roundToStep(value, step));
}

/** The object.changed payload after a drag. */
export function objectChanges(pose: DraggedPose, snap: boolean): Pick<SceneObject, 'position' | 'rotation' | 'scale'> {
  const { x, y, z } = pose.scale;
  return {
    position: position(pose, snap),
    rotation: eulerDegrees(pose.quaternion, snap),
    scale: [scaleFactor(x, snap), scaleFactor(y, snap), scaleFactor(z, snap)],
  };
}

/**
 * The light.changed payload after a drag. An area light's gizmo scales its rig, which
 * multiplies its size (its own y has no meaning: the light is flat).
 */
export function lightChanges(light: Light, pose: DraggedPose, snap: boolean): Partial<Light> {
  if (light.type === 'point') return { position: position(pose, snap) };
  const changes = { position: position(pose, snap), rotation: eulerDegrees(pose.quaternion, snap) };
  if (light.type === 'spot') return changes;
  const [width, depth] = light.size;
  const fit = (size: number) => Math.min(LIMITS.areaSize[1], Math.max(LIMITS.areaSize[0], roundToStep(size, FINE.scale)));
  return { ...changes, size: [fit(width * pose.scale.x), fit(depth * pose.scale.z)] };
}

/**
 * The camera.changed payload after a drag of its rig (local −z is the viewing direction):
 * the target turns with the camera and keeps its distance, so the screen and the rays keep
 * their size and only the view changes.
 */
export function cameraChanges(camera: Camera, pose: DraggedPose, snap: boolean): Pick<Camera, 'position' | 'target'> {
  const distance = eye.set(...camera.position).distanceTo(target.set(...camera.target));
  const newPosition = position(pose, snap);
  forward.set(0, 0, -1).applyQuaternion(pose.quaternion).multiplyScalar(distance);
  const fine = FINE.translate;
  return {
    position: newPosition,
    target: [roundToStep(newPosition[0] + forward.x, fine), roundToStep(newPosition[1] + forward.y, fine), roundToStep(newPosition[2] + forward.z, fine)],
  };
}

const euler = new Euler();
const eye = new Vector3();
const target = new Vector3();
const forward = new Vector3();
