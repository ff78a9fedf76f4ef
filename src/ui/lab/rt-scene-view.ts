import { msg, str } from '@lit/localize';
import { css, html, nothing, type PropertyValues } from 'lit';
import { LocalizedElement } from '../controls/localized-element.ts';
import type { LabState } from '../../lab-state/lab-state.ts';
import type { Store } from '../../lab-state/store.ts';
import { GIZMO_MODES, gizmoModesFor, type GizmoMode } from '../../view/gizmo-modes.ts';
import type { LabView, RayHoverDetail } from '../../view/lab-view.ts';
import type { Thinning } from '../../view/ray-budget.ts';
import { lightsCounted, objectsCounted } from '../../i18n/counted.ts';
import type { ViewCommand } from '../../view/view-commands.ts';
import { LazyModule } from '../../util/lazy-module.ts';
import '../controls/rt-load-problem.ts';
import { GuideHostController } from './guide-host.ts';
import { consumeStore } from './store-context.ts';
import { itemName, shownName } from './scene-names.ts';
import './rt-view-toolbar.ts';
import { guideIds } from '../../quest/lab-controls.ts';
import { isLocked, type MovableItems } from '../../quest/movable-items.ts';

/**
 * The 3D view's code (three.js), loaded after the lab's first render, with a few tries; with
 * it, two parts of the view the first screen can do without, so that their texts are not in
 * its load either: the help dialog of the view's keys and gestures (closed until "?" or Help;
 * opened before its code is there, it opens when that arrives) and the note while the view
 * draws only some of the rays (ray-thinning-text.ts).
 */
const labViewCode = new LazyModule(() => Promise.all([import('../../view/lab-view.ts'), import('./ray-thinning-text.ts'), import('./rt-help-panel.ts')]));

/**
 * @summary The lab's 3D view: a canvas filling the element's box, drawn by a LabView
 * (src/view/lab-view.ts) from `store`, with the on-screen controls and the help dialog
 * laid over it. The canvas takes keyboard focus (arrows orbit, or step the selection in the
 * gizmo's mode, or go to the next pixel; Shift+arrows pan, +/− zoom, T/R/S gizmo, P pixel,
 * Delete, Esc, F, ?; Tab always leaves). What a key did shows in a status line (announced).
 *
 * @fires ray-hover - CustomEvent<RayHoverDetail | null>: the ray under the pointer and where
 *   the pointer is (x, y in CSS px of this element's box), or null when it leaves the rays.
 * @fires view-message - CustomEvent<string>: a change the store refused, or a hint, to show as a toast.
 * @fires view-ready - CustomEvent<LabView>: the three.js view exists and draws (its code loads
 *   after the element's first render, so the panels and the tasks do not wait for three.js).
 * @cssprop --rt-view-bg - The view's background behind the scene (a soft vertical gradient by default).
 */
export class RtSceneView extends LocalizedElement {
  static override properties = {
    store: { attribute: false },
    gizmoControls: { attribute: false },
    movable: { attribute: false },
    state: { state: true },
    atCamera: { state: true },
    helpOpen: { state: true },
    viewProblem: { state: true },
    note: { state: true },
    thinning: { state: true },
  };

  static override styles = css`
    :host {
      position: relative;
      display: block;
      min-height: 200px;
      overflow: hidden;
      /* The toolbar's small-view rules (toolbar-small-view.css.ts) ask this box's size. */
      container-type: size;
      /* Follows the theme (color-scheme on the page, light-dark() as in theme.css). */
      background: var(--rt-view-bg, linear-gradient(180deg, light-dark(#eef1f6, #2b323d) 0%, light-dark(#d3d9e2, #151a21) 100%));
    }
    canvas {
      position: absolute;
      inset: 0;
      display: block;
      width: 100%;
      height: 100%;
      touch-action: none;
      outline: none;
      /* Dragging the view to orbit must not select the page's text on the way. */
      -webkit-user-select: none;
      user-select: none;
    }
    .view-status {
      position: absolute;
      inset: 0;
      display: grid;
      place-items: center;
      margin: 0;
      padding: 1rem;
      text-align: center;
      color: var(--rt-muted, inherit);
    }
    canvas:focus-visible {
      outline: 3px solid var(--rt-accent);
      outline-offset: -3px;
    }
    /* Above the orbit, pan and zoom pads (rt-view-toolbar), whose captions a longer note
       (a Dutch one, a long item name) covered at the bottom: the pads are three rows of
       --rt-target with a caption, padding and border (about 1.6rem), 8px above the view's edge. */
    .note {
      position: absolute;
      left: 50%;
      bottom: calc(3 * var(--rt-target) + 2.5rem);
      max-width: calc(100% - 24px);
      margin: 0;
      padding: 4px 12px;
      border-radius: 6px;
      background: var(--rt-surface);
      color: var(--rt-text);
      box-shadow: var(--rt-shadow);
      font: 0.875rem var(--rt-font);
      transform: translateX(-50%);
      pointer-events: none;
    }
    .note:empty {
      display: none;
    }
    .thinning {
      top: 64px;
      bottom: auto;
    }
  `;

  /** The app's store: the view draws its scene and dispatches selections, gizmo drags and view gestures. */
  declare store: Store | undefined;
  /** The gizmo buttons a level shows (rt-view-toolbar's `gizmoControls`; undefined: all). */
  declare gizmoControls: readonly string[] | undefined;
  /** The only scene items the gizmo, its keys and Delete may change (a level's ui.movable; undefined: all). */
  declare movable: MovableItems;
  declare private state: LabState | undefined;
  declare private atCamera: boolean;
  declare private helpOpen: boolean;
  /** Why the 3D view's code could not be loaded after its tries (offline on a first visit, a newer build), or ''. */
  declare private viewProblem: string;
  /** What the last key did (a step of the selection, the chosen pixel); cleared after NOTE_MS. */
  declare private note: string;
  /** How many rays the view draws of how many while the learner edits (ray-budget.ts), or null: all of them. */
  declare private thinning: Thinning | null;
  private noteTimer: ReturnType<typeof setTimeout> | undefined;
  private view: LabView | null = null;
  /** The words of `thinning` (ray-thinning-text.ts), loaded with the view's code. */
  private thinningText: ((thinning: Thinning) => string) | null = null;
  /** The store a view is being made for while its code loads. */
  private loadingFor: Store | null = null;
  private unsubscribe: (() => void) | null = null;
  private readonly viewCleanups: (() => void)[] = [];
  private readonly resizeObserver = new ResizeObserver(() => this.resize());

  constructor() {
    super();
    this.atCamera = false;
    this.helpOpen = false;
    this.viewProblem = '';
    this.note = '';
    this.thinning = null;
    consumeStore(this, (store) => (this.store = store));
    new GuideHostController(this);
  }

  /** The three.js view (after the first update with a store): setScreenRays, setRayLayer, rasterSnapshot, … */
  get labView(): LabView | null {
    return this.view;
  }

  override connectedCallback(): void {
    super.connectedCallback();
    this.subscribe();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.unsubscribe?.();
    this.unsubscribe = null;
    this.resizeObserver.disconnect();
    for (const cleanup of this.viewCleanups.splice(0)) cleanup();
    this.view?.dispose();
    this.view = null;
  }

  protected override willUpdate(changed: PropertyValues<this>): void {
    if (changed.has('store')) {
      this.unsubscribe?.();
      this.unsubscribe = null;
      if (this.isConnected) this.subscribe();
    }
  }

  protected override updated(changed: PropertyValues<this>): void {
    if (changed.has('store') && this.view && this.view.store !== this.store) {
      for (const cleanup of this.viewCleanups.splice(0)) cleanup();
      this.view.dispose();
      this.view = null;
    }
    if (!this.view && !this.viewProblem && this.store && this.isConnected && this.loadingFor !== this.store) void this.createView(this.store);
    if (this.view && (changed.has('gizmoControls') || changed.has('movable') || changed.has('store'))) this.limitGizmo(this.view);
  }

  override render() {
    const state = this.state;
    return html`
      <canvas tabindex="0" data-guide=${guideIds('view.canvas')} role="img" aria-label=${state ? describe(state) : msg('3D view')}></canvas>
      ${
        this.view
          ? nothing
          : this.viewProblem
            ? html`<div class="view-status"><rt-load-problem .text=${msg('The 3D view could not be loaded.')} .reason=${this.viewProblem}></rt-load-problem></div>`
            : html`<p class="view-status" role="status">${msg('Loading the 3D view…')}</p>`
      }
      <rt-view-toolbar
        .gizmo=${state?.gizmo}
        .allowedModes=${state ? modesShown(state, this.movable) : []}
        .gizmoControls=${this.gizmoControls}
        ?at-camera=${this.atCamera}
        ?pixel-selected=${state?.selectedPixel != null}
        @view-command=${this.onCommand}
        @keydown=${this.onToolbarKey}
      ></rt-view-toolbar>
      <p class="note" role="status">${this.note}</p>
      <p class="note thinning" data-testid="ray-thinning">${this.thinning && this.thinningText ? this.thinningText(this.thinning) : ''}</p>
      <rt-help-panel ?open=${this.helpOpen} @help-closed=${() => (this.helpOpen = false)}></rt-help-panel>
    `;
  }

  private subscribe(): void {
    if (!this.store || this.unsubscribe) return;
    this.state = this.store.state;
    this.unsubscribe = this.store.subscribe((state) => {
      this.state = state;
    });
  }

  private async createView(store: Store): Promise<void> {
    const canvas = this.renderRoot.querySelector('canvas');
    if (!canvas) return;
    this.loadingFor = store;
    let modules;
    try {
      modules = await labViewCode.load();
    } catch {
      this.viewProblem = labViewCode.problem;
      return;
    } finally {
      this.loadingFor = null;
    }
    // The element may have left the page, or got another store, while the code loaded.
    if (this.view || !this.isConnected || this.store !== store) return;
    const [{ LabView }, { thinningText }] = modules;
    this.thinningText = thinningText;
    const view = new LabView(canvas, store);
    this.view = view;
    // The level may have set its limits while the code loaded.
    this.limitGizmo(view);
    this.viewProblem = '';
    this.viewCleanups.push(
      view.onRayHover((detail) => this.fire<RayHoverDetail | null>('ray-hover', detail)),
      view.on('message', (text) => this.fire('view-message', text)),
      view.on('flight', (atCamera) => (this.atCamera = atCamera)),
      view.on('help', () => (this.helpOpen = true)),
      view.on('note', (text) => this.showNote(text)),
      view.on('thinning', (thinning) => (this.thinning = thinning)),
      () => clearTimeout(this.noteTimer),
    );
    this.resizeObserver.observe(this);
    this.resize();
    this.requestUpdate();
    this.fire('view-ready', view);
  }

  private limitGizmo(view: LabView): void {
    view.limitGizmo(this.gizmoControls?.filter(isGizmoMode), this.movable);
  }

  private showNote(text: string): void {
    this.note = text;
    clearTimeout(this.noteTimer);
    this.noteTimer = setTimeout(() => (this.note = ''), NOTE_MS);
  }

  private resize(): void {
    this.view?.setSize(this.clientWidth, this.clientHeight);
  }

  private readonly onCommand = (event: CustomEvent<ViewCommand>) => {
    event.stopPropagation();
    // Toolbar steps glide; the same commands from keys (which repeat) jump.
    this.view?.execute(event.detail, true);
  };

  /** "?" opens the help from the toolbar's buttons too (the canvas handles its own keys). */
  private readonly onToolbarKey = (event: KeyboardEvent) => {
    if (event.key !== '?') return;
    event.preventDefault();
    this.helpOpen = true;
  };

  private fire<T>(type: string, detail: T): void {
    this.dispatchEvent(new CustomEvent<T>(type, { detail, bubbles: true, composed: true }));
  }
}

/** How long a key's note stays up: long enough to read twice, gone before it clutters the view. */
const NOTE_MS = 4000;

/** Modes shown as available: all when nothing is selected (choosing a mode first is fine), none for a locked selection. */
function modesShown(state: LabState, movable: MovableItems) {
  if (isLocked(state.selection, movable)) return [];
  return state.selection ? gizmoModesFor(state.selection, state.scene) : GIZMO_MODES;
}

/** What a screen reader hears for the canvas: the scene in one sentence, and how to move around. */
function describe(state: LabState): string {
  const { scene, selection } = state;
  const name = shownName(scene.name, msg('Untitled scene'));
  const selected =
    selection === null
      ? msg('Nothing is selected.')
      : selection.kind === 'camera'
        ? msg("The ray tracer's camera is selected.")
        : msg(str`Selected: ${itemName(scene, selection.id)}.`);
  return msg(
    str`3D view of "${name}": ${objectsCounted(scene.objects.length)}, ${lightsCounted(scene.lights.length)} and the ray tracer's camera with its ${scene.camera.pixels[0]}×${scene.camera.pixels[1]} screen. ${selected} Arrow keys orbit (with something selected: move it), Shift with arrows pans, plus and minus zoom, P chooses a pixel; press ? for every key.`,
  );
}

customElements.define('rt-scene-view', RtSceneView);

declare global {
  interface HTMLElementTagNameMap {
    'rt-scene-view': RtSceneView;
  }
}

function isGizmoMode(control: string): control is GizmoMode {
  return (GIZMO_MODES as readonly string[]).includes(control);
}
