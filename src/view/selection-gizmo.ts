import { BoxHelper, Group, type Object3D, type PerspectiveCamera } from 'three';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import { cameraChanges, lightChanges, objectChanges } from './gizmo-changes.ts';
import { isLocked, type MovableItems } from '../quest/movable-items.ts';
import { lockedNote } from './locked-note.ts';
import { effectiveGizmoMode, gizmoModesFor, type GizmoMode } from './gizmo-modes.ts';
import { TransformGizmo } from './transform-gizmo.ts';

const SELECTION_COLOR = 0x3b82f6;

/** What the selection's handles need of the rest of the 3D view. */
export interface SelectedParts {
  /** The store's state now. */
  state(): LabState;
  /** The drawn object with this id, if any. */
  objectOf(id: string): Object3D | undefined;
  /** The drawn light gizmo with this id, if any. */
  lightOf(id: string): Object3D | undefined;
  /** The tracer camera's rig (body and screen) and its body alone, which the outline goes around. */
  readonly cameraRig: Object3D;
  readonly cameraBody: Object3D;
  /** The gizmo's look changed (hover highlight, a drag step): draw a frame. */
  changed(): void;
  /** A drag started or stopped (the orbit controls must not move the view meanwhile). */
  draggingChanged(dragging: boolean): void;
  /** A finished drag's change, for the store. */
  dragged(action: LabAction): void;
}

/**
 * The selection as the 3D view shows it: an outline around the selected object, light or
 * camera, and the move/rotate/scale handles on it (transform-gizmo.ts) in a mode the
 * selection and the page allow, which also decides the mode the arrow keys step it in.
 * Apart from LabView so that what a selection offers is decided in one place.
 */
export class SelectionGizmo {
  private readonly gizmo: TransformGizmo;
  /** The selection outline. */
  readonly outline = new BoxHelper(new Group(), SELECTION_COLOR);
  /** The gizmo modes the page offers (a level's gizmo buttons; undefined: all). */
  private offeredModes: readonly GizmoMode[] | undefined = undefined;
  /** The items the page lets the gizmo change (a level's ui.movable; undefined: all). */
  private movableItems: MovableItems = undefined;

  /** Made before the orbit controls: the gizmo's pointerdown must claim a drag before they see it. */
  constructor(
    camera: PerspectiveCamera,
    canvas: HTMLCanvasElement,
    private readonly parts: SelectedParts,
  ) {
    this.gizmo = new TransformGizmo(camera, canvas, {
      changed: () => parts.changed(),
      draggingChanged: (dragging) => parts.draggingChanged(dragging),
      dragEnded: (object, snapped) => this.dragEnded(object, snapped),
    });
  }

  /** The handles, to add to the scene. */
  get helper(): Object3D {
    return this.gizmo.helper;
  }

  get dragging(): boolean {
    return this.gizmo.dragging;
  }

  /** Whether the pointer is over a handle (a click there is not a selection click). */
  get hovering(): boolean {
    return this.gizmo.hovering;
  }

  /**
   * Offers `modes` and lets the gizmo change only `movable` from now on (undefined: all). With
   * no mode, or on a locked item, a selection shows its outline but no handles: a level without
   * move tools shows no arrows, and a level's locked items none either.
   */
  setLimits(modes: readonly GizmoMode[] | undefined, movable: MovableItems, state: LabState): void {
    this.offeredModes = modes;
    this.movableItems = movable;
    this.update(state);
  }

  /** Whether the page keeps the selection where it is: no handles, no key steps, no Delete. */
  locks(state: LabState): boolean {
    return isLocked(state.selection, this.movableItems);
  }

  /** Why the selection stays where it is, for the learner, or null when it is not locked. */
  lockedReason(state: LabState): string | null {
    const { selection } = state;
    if (selection === null || this.movableItems === undefined || !this.locks(state)) return null;
    return lockedNote(state.scene, selection, this.movableItems);
  }

  /** Puts the gizmo and the selection outline on the selection, in a mode it allows. */
  update(state: LabState): void {
    const target = this.selectedObject(state);
    const allowed = gizmoModesFor(state.selection, state.scene);
    const offered = this.offeredModes === undefined || this.offeredModes.some((mode) => allowed.includes(mode));
    const handles = offered && !this.locks(state);
    this.gizmo.setSnapOption(state.gizmo.snap);
    this.gizmo.attach(handles ? target : null, effectiveGizmoMode(state.gizmo.mode, allowed), state.gizmo.space);
    this.outlineSelection(state, target);
  }

  /** Before a frame: the outline follows a drag in progress. */
  followDrag(state: LabState): void {
    if (this.outline.visible && this.gizmo.dragging) this.outlineSelection(state, this.selectedObject(state));
  }

  /**
   * The gizmo mode the arrow keys work in for the selection, or null when its handles are
   * not shown (nothing selected, a level without move tools, a locked item): as the handles,
   * the chosen mode when the selection and the page allow it.
   */
  nudgeMode(state: LabState): GizmoMode | null {
    if (this.locks(state)) return null;
    const allowed = gizmoModesFor(state.selection, state.scene).filter((mode) => this.offeredModes?.includes(mode) ?? true);
    if (allowed.length === 0) return null;
    const mode = effectiveGizmoMode(state.gizmo.mode, gizmoModesFor(state.selection, state.scene));
    return allowed.includes(mode) ? mode : allowed[0]!;
  }

  /** The selection outline: a box around the object or light (around the camera's body only, not its screen). */
  private outlineSelection(state: LabState, target: Object3D | null): void {
    this.outline.visible = target !== null;
    if (target) this.outline.setFromObject(state.selection?.kind === 'camera' ? this.parts.cameraBody : target);
  }

  private selectedObject(state: LabState): Object3D | null {
    const selection = state.selection;
    if (!selection) return null;
    if (selection.kind === 'camera') return this.parts.cameraRig;
    const object = selection.kind === 'object' ? this.parts.objectOf(selection.id) : this.parts.lightOf(selection.id);
    return object ?? null;
  }

  /** A finished drag as the change it made to the selection (the store decides whether it holds). */
  private dragEnded(object: Object3D, snapped: boolean): void {
    const { selection, scene } = this.parts.state();
    const pose = { position: object.position, quaternion: object.quaternion, scale: object.scale };
    let action: LabAction | null = null;
    if (selection?.kind === 'object') action = { type: 'object.changed', id: selection.id, changes: objectChanges(pose, snapped) };
    if (selection?.kind === 'camera') action = { type: 'camera.changed', changes: cameraChanges(scene.camera, pose, snapped) };
    if (selection?.kind === 'light') {
      const light = scene.lights.find((l) => l.id === selection.id);
      if (light) action = { type: 'light.changed', id: light.id, changes: lightChanges(light, pose, snapped) };
    }
    if (action) this.parts.dragged(action);
  }

  dispose(): void {
    this.gizmo.dispose();
    this.outline.dispose();
  }
}
