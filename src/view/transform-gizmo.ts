import type { Object3D, PerspectiveCamera } from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import type { GizmoOptions } from '../lab-state/lab-state.ts';
import type { GizmoMode } from './gizmo-modes.ts';
import { SNAP } from './gizmo-changes.ts';
import { RADIANS_PER_DEGREE } from '../util/angles.ts';

export interface TransformGizmoEvents {
  /** The user let go of a handle after moving it: time to write the new pose to the store. */
  dragEnded(object: Object3D, snapped: boolean): void;
  /** Dragging started or stopped (the orbit controls must not move the view meanwhile). */
  draggingChanged(dragging: boolean): void;
  /** The gizmo's look changed (hover highlight, a drag step): draw a frame. */
  changed(): void;
}

/**
 * The move/rotate/scale gizmo (three.js's TransformControls) on the selected object, light
 * or camera rig. Snapping is on while Shift is held or the Snap option is set. It edits the
 * drawn object during the drag; the store hears of it once, when the handle is let go.
 */
export class TransformGizmo {
  readonly controls: TransformControls;
  private shiftHeld = false;
  private snapOption = false;
  private moved = false;
  private readonly onKey = (event: KeyboardEvent) => this.setShift(event.shiftKey);
  private readonly onBlur = () => this.setShift(false);

  constructor(camera: PerspectiveCamera, canvas: HTMLCanvasElement, events: TransformGizmoEvents) {
    this.controls = new TransformControls(camera, canvas);
    this.controls.setSize(0.9);
    this.controls.addEventListener('change', () => events.changed());
    this.controls.addEventListener('objectChange', () => {
      this.moved = true;
    });
    this.controls.addEventListener('dragging-changed', (event) => {
      const dragging = Boolean(event.value);
      events.draggingChanged(dragging);
      const object = this.controls.object;
      if (dragging) this.moved = false;
      else if (this.moved && object) events.dragEnded(object, this.snapping);
    });
    // Shift anywhere on the page (the pointer is on the canvas, the focus may not be).
    window.addEventListener('keydown', this.onKey);
    window.addEventListener('keyup', this.onKey);
    window.addEventListener('blur', this.onBlur);
  }

  /** The helper to add to the scene (drawn on top of everything it belongs to). */
  get helper(): Object3D {
    return this.controls.getHelper();
  }

  get dragging(): boolean {
    return this.controls.dragging;
  }

  /** Whether the pointer is over a handle (a click there is not a selection click). */
  get hovering(): boolean {
    return this.controls.axis !== null;
  }

  /** Whether a drag ending now would snap. */
  get snapping(): boolean {
    return this.snapOption || this.shiftHeld;
  }

  /** Shows the gizmo on `object` in `mode`, or hides it (null). */
  attach(object: Object3D | null, mode: GizmoMode, space: GizmoOptions['space']): void {
    if (object === null) {
      this.controls.detach();
      return;
    }
    if (this.controls.object !== object) this.controls.attach(object);
    this.controls.setMode(mode);
    this.controls.setSpace(space);
  }

  setSnapOption(snap: boolean): void {
    this.snapOption = snap;
    this.applySnap();
  }

  dispose(): void {
    window.removeEventListener('keydown', this.onKey);
    window.removeEventListener('keyup', this.onKey);
    window.removeEventListener('blur', this.onBlur);
    this.controls.detach();
    this.controls.dispose();
  }

  private setShift(held: boolean): void {
    if (held === this.shiftHeld) return;
    this.shiftHeld = held;
    this.applySnap();
  }

  private applySnap(): void {
    const on = this.snapping;
    this.controls.setTranslationSnap(on ? SNAP.translate : null);
    this.controls.setRotationSnap(on ? SNAP.rotateDegrees * RADIANS_PER_DEGREE : null);
    this.controls.setScaleSnap(on ? SNAP.scale : null);
  }
}
