import { msg, str } from '@lit/localize';
import { type Camera, Quaternion, Vector3 } from 'three';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import type { Vec3 } from '../scene/scene.ts';
import { CameraRays } from '../tracer/camera-rays.ts';
import { sceneQuaternion } from '../tracer/scene-rotation.ts';
import { cameraChanges, type DraggedPose, lightChanges, objectChanges } from './gizmo-changes.ts';
import type { GizmoMode } from './gizmo-modes.ts';
import { NUDGE_STEPS, type NudgeDirection, nudgeStepText } from './nudge-steps.ts';
import { cameraRigQuaternion } from './screen-grid.ts';

/**
 * Moving, turning and scaling the selection with the keyboard, in the gizmo's mode: what a
 * drag on a handle does, one step per key press (WCAG 2.5.7, dragging movements: every drag
 * has a single-pointer or keyboard alternative). The result goes through the same
 * objectChanges / lightChanges / cameraChanges as a finished drag, so the store sees an
 * ordinary object.changed (light.changed, camera.changed) and every level goal that a drag
 * can reach, a key can reach too.
 */

/** The viewer's right and forward directions in the world (the 3D view's own camera). */
export interface ViewAxes {
  right: Vec3;
  forward: Vec3;
}

export interface Nudge {
  mode: GizmoMode;
  direction: NudgeDirection;
  big: boolean;
}

/** The world axis a direction of the view is closest to, among x and z (the floor's axes), with its sign. */
function floorAxis(direction: Vec3): Vector3 {
  const [x, , z] = direction;
  return Math.abs(x) >= Math.abs(z) ? new Vector3(Math.sign(x) || 1, 0, 0) : new Vector3(0, 0, Math.sign(z) || 1);
}

/**
 * Where each key moves or turns things: left/right along the floor axis closest to the
 * viewer's right, up/down along y, Page Up/Down along the floor axis closest to the viewer's
 * forward. Snapping to world axes keeps the numbers in the panels round (x goes from −0.8
 * to −0.7, not to −0.713 and z 0.04).
 */
function keyAxes(direction: NudgeDirection, axes: ViewAxes): { axis: Vector3; sign: 1 | -1 } {
  const right = floorAxis(axes.right);
  const forward = floorAxis(axes.forward);
  switch (direction) {
    case 'right':
      return { axis: right, sign: 1 };
    case 'left':
      return { axis: right, sign: -1 };
    case 'up':
      return { axis: new Vector3(0, 1, 0), sign: 1 };
    case 'down':
      return { axis: new Vector3(0, 1, 0), sign: -1 };
    case 'farther':
      return { axis: forward, sign: 1 };
    case 'nearer':
      return { axis: forward, sign: -1 };
  }
}

/**
 * The turn for a key: left/right turn about the vertical (right turns clockwise seen from
 * above), up/down tilt about the viewer's right axis (up tips the top away from the viewer),
 * Page Up/Down roll about the viewing direction.
 */
function turn(direction: NudgeDirection, axes: ViewAxes, degrees: number): Quaternion {
  const angle = (degrees * Math.PI) / 180;
  const about = (axis: Vector3, sign: number) => new Quaternion().setFromAxisAngle(axis, sign * angle);
  switch (direction) {
    case 'right':
      return about(new Vector3(0, 1, 0), -1);
    case 'left':
      return about(new Vector3(0, 1, 0), 1);
    case 'up':
      return about(floorAxis(axes.right), -1);
    case 'down':
      return about(floorAxis(axes.right), 1);
    case 'farther':
      return about(floorAxis(axes.forward), 1);
    case 'nearer':
      return about(floorAxis(axes.forward), -1);
  }
}

/** The pose of the selection now, as a drag would start from it; null when there is none. */
function currentPose(state: Pick<LabState, 'scene' | 'selection'>): DraggedPose | null {
  const { scene, selection } = state;
  if (selection?.kind === 'object') {
    const object = scene.objects.find((o) => o.id === selection.id);
    if (!object) return null;
    return { position: new Vector3(...object.position), quaternion: sceneQuaternion(object.rotation), scale: new Vector3(...object.scale) };
  }
  if (selection?.kind === 'light') {
    const light = scene.lights.find((l) => l.id === selection.id);
    if (!light) return null;
    // An area light's size is its gizmo rig's scale 1 (lightChanges multiplies it).
    const rotation = light.type === 'point' ? new Quaternion() : sceneQuaternion(light.rotation);
    return { position: new Vector3(...light.position), quaternion: rotation, scale: new Vector3(1, 1, 1) };
  }
  if (selection?.kind === 'camera') {
    const rays = new CameraRays(scene.camera);
    return { position: rays.eye.clone(), quaternion: cameraRigQuaternion(rays, new Quaternion()), scale: new Vector3(1, 1, 1) };
  }
  return null;
}

function moved(pose: DraggedPose, { mode, direction, big }: Nudge, axes: ViewAxes): DraggedPose {
  const next = { position: pose.position.clone(), quaternion: pose.quaternion.clone(), scale: pose.scale.clone() };
  if (mode === 'translate') {
    const { axis, sign } = keyAxes(direction, axes);
    next.position.addScaledVector(axis, sign * NUDGE_STEPS.translate[big ? 'big' : 'small']);
  } else if (mode === 'rotate') {
    next.quaternion.premultiply(turn(direction, axes, NUDGE_STEPS.rotate[big ? 'big' : 'small']));
  } else {
    const factor = NUDGE_STEPS.scale[big ? 'big' : 'small'];
    next.scale.multiplyScalar(direction === 'up' || direction === 'right' || direction === 'farther' ? factor : 1 / factor);
  }
  return next;
}

/**
 * The action one key press makes of the selection in gizmo mode `nudge.mode` (a mode the
 * selection allows: see gizmoModesFor), or null when nothing is selected.
 */
export function nudgeAction(state: Pick<LabState, 'scene' | 'selection'>, nudge: Nudge, axes: ViewAxes): LabAction | null {
  const pose = currentPose(state);
  const selection = state.selection;
  if (!pose || !selection) return null;
  const next = moved(pose, nudge, axes);
  // Rounded as a drag without snapping is: clean numbers, nothing lost that a key could add.
  if (selection.kind === 'object') return { type: 'object.changed', id: selection.id, changes: objectChanges(next, false) };
  if (selection.kind === 'camera') return { type: 'camera.changed', changes: cameraChanges(state.scene.camera, next, false) };
  const light = state.scene.lights.find((l) => l.id === selection.id)!;
  return { type: 'light.changed', id: light.id, changes: lightChanges(light, next, false) };
}

/** The viewer's right and forward directions, from the 3D view's own camera. */
export function viewAxesOf(camera: Camera): ViewAxes {
  const forward = camera.getWorldDirection(new Vector3());
  const right = new Vector3().crossVectors(forward, camera.up).normalize();
  return { right: [right.x, right.y, right.z], forward: [forward.x, forward.y, forward.z] };
}

/** What the learner reads after a key press: what moved, by how much, and the Shift step. */
export function nudgeNote(name: string, mode: GizmoMode, big: boolean): string {
  const step = nudgeStepText(mode, big);
  const other = nudgeStepText(mode, !big);
  const shift = big ? msg(str`Without Shift: ${other}.`) : msg(str`With Shift: ${other}.`);
  if (mode === 'translate') return `${msg(str`${name} moved ${step}.`)} ${shift}`;
  if (mode === 'rotate') return `${msg(str`${name} turned ${step}.`)} ${shift}`;
  return `${msg(str`${name} scaled ${step}.`)} ${shift}`;
}
