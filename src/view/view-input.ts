import { msg } from '@lit/localize';
import { type Object3D, type PerspectiveCamera, Raycaster } from 'three';
import { itemName } from '../i18n/scene-item-names.ts';
import type { Issue } from '../util/issue.ts';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import type { Store } from '../lab-state/store.ts';
import { nudgeAction, nudgeNote, viewAxesOf } from './gizmo-nudge.ts';
import { Picker, type PickResult } from './picking.ts';
import type { RayHover, RayLayer } from './ray-layer.ts';
import type { SelectionGizmo } from './selection-gizmo.ts';
import { sameSelection, stateCommand, type StateCommand } from './state-commands.ts';
import { type ArrowTarget, keyCommand, type ViewCommand } from './view-commands.ts';
import type { ViewNavigation } from './view-navigation.ts';

/** A pointer press that moves less than this (CSS px) before release is a click, not a drag. */
const CLICK_SLOP = 6;

/** The hovered ray and where the pointer is, for a tooltip next to it. */
export interface RayHoverDetail {
  hover: RayHover;
  /** CSS px from the canvas's top-left corner. */
  x: number;
  y: number;
  clientX: number;
  clientY: number;
}

/** What the input needs of the rest of the 3D view. */
export interface InputParts {
  /** What a click can select: the drawn objects, the light gizmos, the camera rig with its screen. */
  readonly pickable: Object3D[];
  readonly selection: SelectionGizmo;
  readonly navigation: ViewNavigation;
  /** The drawn rays, or null. */
  rayLayer(): RayLayer | null;
  /** Dispatches, showing the reasons when the store refuses. Returns them. */
  dispatch(action: LabAction): Issue[] | undefined;
  /** The ray under the pointer, or null when it leaves the rays. */
  rayHover(detail: RayHoverDetail | null): void;
  /** Something to tell the user (a toast). */
  message(text: string): void;
  /** What a key did, to show and announce. */
  note(text: string): void;
  /** The user pressed "?". */
  help(): void;
}

/**
 * The 3D view's pointer and keys: a click (a press that hardly moves) selects what it hits
 * or chooses a screen pixel, hovering a ray shows its tooltip, and a key or toolbar button
 * runs a view command (view-commands.ts): navigation, a step of the selection in its gizmo
 * mode, or a change of the lab's state. Apart from LabView so that what a gesture means is
 * read in one place.
 */
export class ViewInput {
  private readonly picker = new Picker();
  private readonly rayRaycaster = new Raycaster();
  private readonly cleanups: (() => void)[] = [];
  private lastHover: RayHover | null = null;
  private press: { id: number; x: number; y: number; onGizmo: boolean } | null = null;
  private hoverQueued = false;
  private pointer: { x: number; y: number } | null = null;

  /** Listens on `canvas`; made after the gizmo and the orbit controls, which see a press first. */
  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: PerspectiveCamera,
    private readonly store: Store,
    private readonly parts: InputParts,
  ) {
    this.listen(canvas, 'pointerdown', (event) => this.pointerDown(event));
    this.listen(canvas, 'pointerup', (event) => this.pointerUp(event));
    this.listen(canvas, 'pointermove', (event) => this.pointerMoved(event));
    this.listen(canvas, 'pointerleave', () => this.pointerLeft());
    this.listen(canvas, 'keydown', (event) => this.keyDown(event));
  }

  /** What a click at (clientX, clientY) would select: an object, a light, the camera, a screen pixel, or null for empty space. */
  pickAt(clientX: number, clientY: number): PickResult | null {
    this.picker.aim(this.camera, this.canvas, clientX, clientY);
    return this.picker.pick(this.parts.pickable);
  }

  /** Does what a key or a toolbar button asks; `glide` spreads a step over a few frames (buttons). */
  execute(command: ViewCommand, glide = false): void {
    const state = this.store.state;
    const navigation = this.parts.navigation;
    switch (command.kind) {
      case 'orbit':
        return navigation.orbit(command.dxDeg, command.dyDeg, glide);
      case 'pan':
        return navigation.pan(command.dx, command.dy, glide);
      case 'zoom':
        return navigation.zoom(command.factor, glide);
      case 'escape':
        if (navigation.atCamera) navigation.flyBack();
        return this.apply(stateCommand(command, state));
      case 'fly':
        return navigation.atCamera ? navigation.flyBack() : navigation.flyToCamera();
      case 'show-pixel-rays':
        return navigation.showPixelRays();
      case 'help':
        return this.parts.help();
      case 'nudge':
        return this.nudge(command);
      case 'delete':
        return this.refuseLocked(state) ? undefined : this.apply(stateCommand(command, state));
      case 'gizmo-mode':
        // A locked selection has no handles to switch: T, R and S say why, as a drag does, and leave the mode as it was.
        return this.refuseLocked(state) ? undefined : this.apply(stateCommand(command, state));
      default:
        return this.apply(stateCommand(command, state));
    }
  }

  /** Dispatches a command's action and shows its message (or, when it went through, its note). */
  private apply(command: StateCommand | null): void {
    const refused = command?.action ? this.parts.dispatch(command.action) : undefined;
    if (command?.message) this.parts.message(command.message);
    if (command?.note && !refused) this.parts.note(command.note);
  }

  /** A locked selection (a level's ui.movable) stays: the learner reads why. Whether it was locked. */
  private refuseLocked(state: LabState): boolean {
    const reason = this.parts.selection.lockedReason(state);
    if (reason) this.parts.note(reason);
    return reason !== null;
  }

  private arrowTarget(state: LabState): ArrowTarget {
    // The arrows try to move a locked selection too, so that they say why it stays.
    if (this.parts.selection.nudgeMode(state) || this.parts.selection.locks(state)) return 'selection';
    return state.selectedPixel ? 'pixel' : 'view';
  }

  /** One key step of the selection in its gizmo mode, along the world axes nearest the viewer's. */
  private nudge(command: Extract<ViewCommand, { kind: 'nudge' }>): void {
    const state = this.store.state;
    if (this.refuseLocked(state)) return;
    const mode = this.parts.selection.nudgeMode(state);
    const action = mode && nudgeAction(state, { mode, direction: command.direction, big: command.big }, viewAxesOf(this.camera));
    if (!mode || !action || this.parts.dispatch(action)) return;
    this.parts.note(nudgeNote(this.selectionName(state), mode, command.big));
  }

  private selectionName({ scene, selection }: LabState): string {
    if (selection?.kind === 'object' || selection?.kind === 'light') return itemName(scene, selection.id);
    return msg("The ray tracer's camera");
  }

  private pointerDown(event: PointerEvent): void {
    if (!event.isPrimary) {
      this.press = null;
      return;
    }
    const gizmo = this.parts.selection;
    this.press = { id: event.pointerId, x: event.clientX, y: event.clientY, onGizmo: gizmo.hovering || gizmo.dragging };
  }

  private pointerUp(event: PointerEvent): void {
    const press = this.press;
    this.press = null;
    if (!press || press.id !== event.pointerId || press.onGizmo || event.button !== 0) return;
    if (Math.hypot(event.clientX - press.x, event.clientY - press.y) > CLICK_SLOP) return;
    if (this.clickRay(event.clientX, event.clientY)) return;
    this.click(this.pickAt(event.clientX, event.clientY));
  }

  /** A click on a drawn ray that the rays' owner takes (a path vertex for the path debugger) selects nothing else. */
  private clickRay(clientX: number, clientY: number): boolean {
    const rayLayer = this.parts.rayLayer();
    if (!rayLayer) return false;
    this.picker.aim(this.camera, this.canvas, clientX, clientY);
    const hover = this.pickRay(rayLayer);
    return hover !== null && rayLayer.click(hover);
  }

  /** The drawn ray along the picker's aimed ray, or null. */
  private pickRay(rayLayer: RayLayer): RayHover | null {
    this.rayRaycaster.ray.copy(this.picker.raycaster.ray);
    this.rayRaycaster.camera = this.camera;
    return rayLayer.pick(this.rayRaycaster);
  }

  /** A click selects what it hit, toggles a screen pixel, or deselects on empty space. */
  private click(hit: PickResult | null): void {
    const state = this.store.state;
    if (hit === null) {
      if (state.selection) this.parts.dispatch({ type: 'selection.changed', selection: null });
      return;
    }
    if (hit.kind === 'pixel') {
      const [x, y] = hit.pixel;
      const again = state.selectedPixel?.[0] === x && state.selectedPixel[1] === y;
      this.parts.dispatch(again ? { type: 'pixel.deselected' } : { type: 'pixel.selected', pixel: hit.pixel });
      return;
    }
    const selection = hit.kind === 'camera' ? { kind: 'camera' as const } : hit;
    if (!sameSelection(state.selection, selection)) this.parts.dispatch({ type: 'selection.changed', selection });
  }

  /** Hover work waits for the next frame: one pick per frame however fast the pointer moves. */
  private pointerMoved(event: PointerEvent): void {
    if (event.pointerType === 'touch') return;
    this.pointer = { x: event.clientX, y: event.clientY };
    if (this.hoverQueued) return;
    this.hoverQueued = true;
    requestAnimationFrame(() => {
      this.hoverQueued = false;
      this.hover();
    });
  }

  private hover(): void {
    const pointer = this.pointer;
    if (!pointer || this.parts.selection.dragging || this.press) return;
    const hit = this.pickAt(pointer.x, pointer.y);
    this.canvas.style.cursor = hit ? 'pointer' : '';
    const rayLayer = this.parts.rayLayer();
    const hover = rayLayer ? this.pickRay(rayLayer) : null;
    // Over a ray the tooltip follows the pointer; off rays, one null says so.
    if (hover === null && this.lastHover === null) return;
    this.lastHover = hover;
    const rect = this.canvas.getBoundingClientRect();
    const at = { x: pointer.x - rect.left, y: pointer.y - rect.top, clientX: pointer.x, clientY: pointer.y };
    this.parts.rayHover(hover ? { hover, ...at } : null);
  }

  private pointerLeft(): void {
    this.pointer = null;
    this.canvas.style.cursor = '';
    if (this.lastHover) {
      this.lastHover = null;
      this.parts.rayHover(null);
    }
  }

  private keyDown(event: KeyboardEvent): void {
    const command = keyCommand(event, this.arrowTarget(this.store.state));
    if (!command) return;
    event.preventDefault();
    this.execute(command);
  }

  private listen<K extends keyof HTMLElementEventMap>(target: HTMLElement, type: K, handler: (event: HTMLElementEventMap[K]) => void): void {
    target.addEventListener(type, handler);
    this.cleanups.push(() => target.removeEventListener(type, handler));
  }

  /** Stops listening. */
  dispose(): void {
    for (const cleanup of this.cleanups) cleanup();
  }
}
