import type { Issue } from '../util/issue.ts';
import { issueText } from '../i18n/issue-text.ts';
import { msg, str } from '@lit/localize';
import {
  ColorManagement,
  GridHelper,
  HemisphereLight,
  type Object3D,
  type PerspectiveCamera,
  type Scene as ThreeScene,
  Vector3,
  type WebGLRenderer,
} from 'three';
import type { LabAction } from '../lab-state/lab-action.ts';
import type { LabState } from '../lab-state/lab-state.ts';
import { loadMeshes } from '../render/load-meshes-browser.ts';
import type { ScreenRays } from '../render/screen-rays.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import type { Store } from '../lab-state/store.ts';
import type { Vec3 } from '../scene/scene.ts';
import { CameraScreen } from './camera-screen.ts';
import { CaseOverlay } from './case-overlay.ts';
import { DistributionGizmos } from './distribution-gizmos.ts';
import type { Animator } from './frame-scheduler.ts';
import type { GizmoMode } from './gizmo-modes.ts';
import { LightGizmos } from './light-gizmos.ts';
import type { PickResult } from './picking.ts';
import { RasterLights } from './raster-lights.ts';
import { rasterSnapshot } from './raster-snapshot.ts';
import type { RayLayer } from './ray-layer.ts';
import { type MeshLoader, SceneSync } from './scene-sync.ts';
import { SelectionGizmo } from './selection-gizmo.ts';
import type { MovableItems } from '../quest/movable-items.ts';
import type { ViewCommand } from './view-commands.ts';
import { type RayHoverDetail, ViewInput } from './view-input.ts';
import { rayPathPoints, rayPathPointsFromHit, raySegmentsOnCanvas, type CanvasPoint } from './ray-path-points.ts';
import { framedRaysPixel } from '../lab-state/framed-rays.ts';
import { ViewProbes } from './view-probes.ts';
import { ViewDrawing } from './view-drawing.ts';
import { ViewNavigation } from './view-navigation.ts';
import type { Thinning } from './ray-budget.ts';
import { framedPoints } from './view-look.ts';

export type { RayHoverDetail } from './view-input.ts';

interface LabViewEvents {
  rayHover: RayHoverDetail | null;
  /** A refused change or a failure, to show the user (a toast). */
  message: string;
  /** Whether the view is at the ray tracer's camera (with a way back). */
  flight: boolean;
  /** The user pressed "?". */
  help: undefined;
  /** What a key did (a step of the selection, the chosen pixel), to show and announce. */
  note: string;
  /** How many rays are drawn of how many while the learner edits (null: all of them). */
  thinning: Thinning | null;
}

type Listener<T> = (value: T) => void;

/** Nearer than this to the tracer camera's eye, its body would fill the view: hide it. */
const INSIDE_CAMERA = 0.35;

/** Multisampling of the render window's raster picture on a GPU (none on a CPU rasterizer, as the view itself). */
const SNAPSHOT_SAMPLES = 4;

/**
 * The lab's 3D view: the scene from the store drawn with three.js (objects with a Phong look,
 * lights as gizmos, the ray tracer's camera and its screen), kept in step with the store, and
 * the one object the page talks to. Its parts each hold one concept: drawing and when it
 * happens (view-drawing.ts), where the user looks from (view-navigation.ts), the selection's
 * outline and handles (selection-gizmo.ts), pointer and keys (view-input.ts), and what browser
 * tests read off the view (view-probes.ts). Draws only when something changed.
 *
 * Colours are display values throughout, as in the ray tracer (no gamma): three.js's colour
 * management is switched off and the canvas shows the linear values as they are, so an
 * object's colour, its traced pixel and a hex colour in CSS all look the same.
 */
export class LabView {
  readonly renderer: WebGLRenderer;
  readonly scene: ThreeScene;
  /** The user's viewpoint (not the ray tracer's camera). */
  readonly camera: PerspectiveCamera;
  /** WebGL draws on a CPU rasterizer (ViewDrawing.software). */
  readonly software: boolean;
  /** The renderer, frames on demand, sizes and the CPU rasterizer's economies (view-drawing.ts). */
  private readonly drawing: ViewDrawing;
  /** Orbit, pan, zoom, flights and framing (view-navigation.ts). */
  private readonly navigation: ViewNavigation;
  /** Pointer, keys, picking and view commands (view-input.ts). */
  private readonly input: ViewInput;
  /** The selection's outline and handles (selection-gizmo.ts). */
  private readonly selection: SelectionGizmo;
  private readonly objects: SceneSync;
  private readonly rasterLights: RasterLights;
  private readonly lightGizmos: LightGizmos;
  private readonly cameraScreen: CameraScreen;
  private readonly distribution: DistributionGizmos;
  /** A code lab's failing case, drawn and framed (case-overlay.ts); browser tests read `labCase.shown`. */
  readonly labCase = new CaseOverlay({
    frame: (...framing) => this.navigation.showPoints(...framing),
    drawn: (shown) => this.drawing.setRaysAside(shown),
    store: this.store,
  });
  private readonly grid: GridHelper;
  private readonly listeners: { [K in keyof LabViewEvents]: Set<Listener<LabViewEvents[K]>> } = {
    rayHover: new Set(),
    message: new Set(),
    flight: new Set(),
    help: new Set(),
    note: new Set(),
    thinning: new Set(),
  };
  private readonly unsubscribe: () => void;
  private previous: LabState | null = null;
  /** The camera's pixels' latest rays (for "show its rays"). */
  private screenRays: ScreenRays | null = null;
  /** For browser tests and tools: what the view shows, read off it (view-probes.ts). */
  readonly probes: ViewProbes;
  /** The thinning the last drawn frame showed, as last told. */
  private drawnThinning: Thinning | null = null;
  /** A scene was loaded and nothing drawn since: a declared look then jumps instead of gliding. */
  private sceneJustLoaded = false;

  constructor(
    readonly canvas: HTMLCanvasElement,
    readonly store: Store,
    meshLoader: MeshLoader = loadMeshes,
  ) {
    // Before any colour is made (so no part is a field initializer, which runs before this):
    // with management on, hex colours would be linearized.
    ColorManagement.enabled = false;
    this.distribution = new DistributionGizmos();
    this.rasterLights = new RasterLights();
    this.lightGizmos = new LightGizmos();
    this.cameraScreen = new CameraScreen();
    this.grid = new GridHelper(20, 20, 0x6b7686, 0x8a94a3);
    this.drawing = new ViewDrawing(canvas, {
      beforeDraw: () => this.beforeDraw(),
      drawn: () => this.drawn(),
      // The first framing guessed a square view; frame again for the real shape.
      firstSized: () => {
        this.navigation.frameScene();
        this.navigation.follow(this.store.state.look, false);
      },
    });
    this.renderer = this.drawing.renderer;
    this.scene = this.drawing.scene;
    this.camera = this.drawing.camera;
    this.software = this.drawing.software;

    // The gizmo first: its pointerdown must claim a drag before the orbit controls see it.
    this.selection = new SelectionGizmo(this.camera, canvas, {
      state: () => this.store.state,
      objectOf: (id) => this.objects.objectOf(id),
      lightOf: (id) => this.lightGizmos.objectOf(id),
      cameraRig: this.cameraScreen.rig,
      cameraBody: this.cameraScreen.body,
      changed: () => this.requestRender(),
      draggingChanged: (dragging) => this.navigation.pauseGestures(dragging),
      // A refused drag is shown, and the drawing, left where the drag put it, is put back.
      dragged: (action) => {
        if (this.dispatch(action)) this.resync();
      },
    });
    this.navigation = new ViewNavigation(this.camera, canvas, this.drawing.scheduler, store, {
      pointsOf: (name) => this.framedPointsOf(name),
      pixelRayPoints: () => this.pixelRayPoints(),
      dispatch: (action) => this.dispatch(action),
      flightChanged: (atCamera) => this.emit('flight', atCamera),
      message: (text) => this.emit('message', text),
    });
    this.objects = new SceneSync(meshLoader, (error) => {
      if (error) this.emit('message', msg(str`A model could not be loaded: ${error}`));
      this.requestRender();
    });

    this.grid.position.y = 0.002;
    // A faint floor grid: orientation without competing with the scene.
    this.grid.material.transparent = true;
    this.grid.material.opacity = 0.28;
    this.grid.material.depthWrite = false;
    this.scene.add(
      new HemisphereLight(0xffffff, 0x5a6270, 0.55),
      this.grid,
      this.objects.group,
      this.rasterLights.group,
      this.lightGizmos.group,
      this.cameraScreen.rig,
      this.distribution.group,
      this.labCase.group,
      this.selection.outline,
      this.selection.helper,
    );

    this.probes = new ViewProbes({
      renderer: this.renderer,
      scene: this.scene,
      camera: this.camera,
      rayLayer: () => this.drawing.rayLayer,
      caseLayer: this.labCase.group,
      allRaysDrawn: () => this.drawing.allRaysDrawn,
      idle: () => this.drawing.scheduler.idle,
      traceOf: (pixel) => this.traceOf(pixel),
      framedPointsOf: (name) => this.framedPointsOf(name),
      projectToView: (point) => this.projectToView(point),
      opaque: this.objects.group,
      requestRender: () => this.requestRender(),
    });

    this.input = new ViewInput(canvas, this.camera, store, {
      pickable: [this.objects.group, this.lightGizmos.group, this.cameraScreen.rig],
      selection: this.selection,
      navigation: this.navigation,
      rayLayer: () => this.drawing.rayLayer,
      dispatch: (action) => this.dispatch(action),
      rayHover: (detail) => this.emit('rayHover', detail),
      message: (text) => this.emit('message', text),
      note: (text) => this.emit('note', text),
      help: () => this.emit('help', undefined),
    });
    this.unsubscribe = store.subscribe((state, action) => {
      this.update(state);
      if (action.type === 'scene.loaded') {
        this.navigation.sceneLoaded();
        this.sceneJustLoaded = true;
      }
    });
    this.update(store.state);
    this.navigation.frameScene();
    this.navigation.follow(store.state.look, false);
  }

  /** Whether the view is still on its way: a flight or glide under way, or a framing waiting for its pixel's rays. */
  get moving(): boolean {
    return this.navigation.moving;
  }

  /** How many frames were drawn so far (idle means it stops growing). */
  get frameCount(): number {
    return this.drawing.frameCount;
  }

  /** Draws one frame soon (call after changing anything drawn, like the ray layer's content). */
  requestRender(): void {
    this.drawing.requestRender();
  }

  /** Calls `animator` every frame; frames keep coming while it returns true. Returns its remover. */
  addAnimator(animator: Animator): () => void {
    return this.drawing.addAnimator(animator);
  }

  /** The canvas's size in CSS pixels; drawn at up to 2 device pixels per CSS pixel (school laptops). */
  setSize(width: number, height: number): void {
    this.drawing.setSize(width, height);
  }

  /** Colours the camera's screen with the traced pixels. */
  setScreenRays(rays: ScreenRays): void {
    this.screenRays = rays;
    this.cameraScreen.setScreenRays(rays);
    this.navigation.raysArrived();
    this.drawing.raysArrived();
  }

  /** Shows the drawn rays (replacing any before), animates them and picks them for hover. */
  setRayLayer(layer: RayLayer | null): void {
    this.drawing.setRayLayer(layer);
  }

  /** On a CPU rasterizer: draws coarse while the drawn rays are thinned to `budget`, sharp at once after (null). */
  holdCoarse(budget: number | null): void {
    this.drawing.holdCoarse(budget);
  }

  /** Shows the acceleration boxes (BvhBoxes.object), replacing any before; null removes them. */
  setBvhLayer(object: Object3D | null): void {
    this.drawing.setBvhLayer(object);
  }

  /** Calls `listener` with the ray under the pointer (or null when it leaves it). Returns its remover. */
  onRayHover(listener: Listener<RayHoverDetail | null>): () => void {
    return this.on('rayHover', listener);
  }

  on<K extends keyof LabViewEvents>(type: K, listener: Listener<LabViewEvents[K]>): () => void {
    const set = this.listeners[type] as Set<Listener<LabViewEvents[K]>>;
    set.add(listener);
    return () => set.delete(listener);
  }

  /** Does what a key or a toolbar button asks; `glide` spreads a step over a few frames (buttons). */
  execute(command: ViewCommand, glide = false): void {
    this.input.execute(command, glide);
  }

  /** Orbits the view as a toolbar button does: +dx moves the eye right around the target, +dy up. */
  orbit(dxDeg?: number, dyDeg?: number): void {
    this.navigation.orbit(dxDeg, dyDeg);
  }

  /** Pans as a toolbar button does: shares of the visible height, +dx right, +dy up. */
  pan(dx?: number, dy?: number): void {
    this.navigation.pan(dx, dy);
  }

  /** Zooms as a toolbar button does: factor > 1 moves closer. */
  zoom(factor?: number): void {
    this.navigation.zoom(factor);
  }

  /** Glides to the ray tracer's camera (eye, target, fov); reports view.flew-to-camera on arrival. */
  flyToCamera(): void {
    this.navigation.flyToCamera();
  }

  /** "Show its rays": glides to where the chosen pixel's whole ray path (and the camera it starts at) fits the view. */
  showPixelRays(): void {
    this.navigation.showPixelRays();
  }

  /**
   * How much of the canvas's bottom (CSS px) panels over the view cover (the pixel preview,
   * the ray debugger): framing then fits what it shows into the part above.
   */
  setCoveredBottom(px: number): void {
    this.navigation.setCoveredBottom(px);
  }

  /** The chosen pixel's latest trace, or null without a pixel or its trace. */
  private selectedTrace(): PixelTrace | null {
    const pixel = this.store.state.selectedPixel;
    return pixel ? this.traceOf(pixel) : null;
  }

  /** Pixel `pixel`'s latest trace, chosen or not (null before it is traced). */
  private traceOf(pixel: readonly [number, number]): PixelTrace | null {
    return this.screenRays?.traces.find((candidate) => candidate.pixel[0] === pixel[0] && candidate.pixel[1] === pixel[1]) ?? null;
  }

  /** The chosen pixel's whole ray path and the camera it starts at, or null without a pixel or its trace. */
  private pixelRayPoints(): Vec3[] | null {
    const trace = this.selectedTrace();
    return trace ? [...rayPathPoints(trace), this.store.state.scene.camera.position] : null;
  }

  /** The raster view from the ray tracer's camera, `width`×`height`, for the render window's comparison. */
  rasterSnapshot(width: number, height: number): Promise<ImageData> {
    const hidden: Object3D[] = [
      this.grid,
      this.lightGizmos.group,
      this.cameraScreen.rig,
      this.distribution.group,
      this.labCase.group,
      this.selection.outline,
      this.selection.helper,
    ];
    const { rayLayer, bvhLayer } = this.drawing;
    if (rayLayer) hidden.push(rayLayer.object);
    if (bvhLayer) hidden.push(bvhLayer);
    const { camera, settings } = this.store.state.scene;
    return rasterSnapshot(this.renderer, this.scene, hidden, camera, settings.background, width, height, this.software ? 0 : SNAPSHOT_SAMPLES);
  }

  /** The world points a declared view fits for `name` (view-look.ts), from what is drawn now and the latest trace. */
  private framedPointsOf(name: string): Vec3[] {
    const pixel = framedRaysPixel(name);
    if (pixel) {
      const trace = this.traceOf(pixel);
      return trace ? rayPathPointsFromHit(trace) : [];
    }
    const drawn = (id: string) => this.objects.objectOf(id) ?? this.lightGizmos.objectOf(id);
    return framedPoints(name, this.store.state.scene, drawn, this.cameraScreen.rig);
  }

  /** The chosen pixel's rays as segments on the canvas (CSS px), none without a pixel or its trace: where the pixel preview must not cover them (preview-place.ts). */
  pixelRaySegments(): { from: CanvasPoint; to: CanvasPoint }[] {
    return raySegmentsOnCanvas(this.selectedTrace(), (point) => this.projectToView(point));
  }

  /** Where a world point appears on the canvas (CSS px from its top-left), or null behind the eye. */
  projectToView(point: Vec3): { x: number; y: number } | null {
    const p = projected.set(...point).project(this.camera);
    if (p.z > 1) return null;
    const rect = this.canvas.getBoundingClientRect();
    return { x: ((p.x + 1) / 2) * rect.width, y: ((1 - p.y) / 2) * rect.height };
  }

  /** What a click at (clientX, clientY) would select: an object, a light, the camera, a screen pixel, or null for empty space. */
  pickAt(clientX: number, clientY: number): PickResult | null {
    return this.input.pickAt(clientX, clientY);
  }

  dispose(): void {
    this.unsubscribe();
    this.input.dispose();
    this.drawing.stop();
    this.navigation.dispose();
    this.selection.dispose();
    this.objects.dispose();
    this.rasterLights.dispose();
    this.lightGizmos.dispose();
    this.cameraScreen.dispose();
    this.distribution.dispose();
    this.labCase.dispose();
    this.grid.dispose();
    this.drawing.dispose();
  }

  // --- store → drawing ---

  private update(state: LabState): void {
    // A fact (render.started, view.orbited, …) changes nothing drawn. A frame for it made a
    // page composited on the CPU read the canvas back at Render, waiting 110–150 ms for the
    // software GPU to finish the render window's raster picture first.
    if (state === this.previous) return;
    const previous = this.previous;
    this.previous = state;
    // A level's first view is where it starts, not a flight away from the scene's framing.
    if (previous && state.look !== previous.look) this.navigation.follow(state.look, !this.sceneJustLoaded);
    if (state.scene !== previous?.scene) {
      this.objects.sync(state.scene);
      this.rasterLights.sync(state.scene);
      this.lightGizmos.sync(state.scene);
      if (previous && !sameCamera(previous, state)) this.navigation.cameraEdited();
    }
    // A moving object's copies show the chosen pixel's moments where each pixel has its own.
    if (state.scene !== previous?.scene || state.selectedPixel !== previous.selectedPixel) {
      this.distribution.sync(state.scene, (id) => this.objects.objectOf(id), state.selectedPixel);
    }
    if (state.scene !== previous?.scene || state.selectedPixel !== previous.selectedPixel || state.rays.showSamplePoints !== previous.rays.showSamplePoints) {
      this.cameraScreen.sync({
        camera: state.scene.camera,
        settings: state.scene.settings,
        selectedPixel: state.selectedPixel,
        showSamplePoints: state.rays.showSamplePoints,
      });
    }
    if (!this.selection.dragging) this.selection.update(state);
    // A newly selected locked item shows no handles: the learner reads why, however it was selected.
    const locked = state.selection !== previous?.selection ? this.selection.lockedReason(state) : null;
    if (locked) this.emit('note', locked);
    if (previous && state.scene !== previous.scene) this.drawing.sceneEdited();
    this.requestRender();
  }

  /** What the page lets the gizmo do: the modes a level offers and the items it may change (ui.movable); undefined: all (selection-gizmo.ts). */
  limitGizmo(modes: readonly GizmoMode[] | undefined, movable: MovableItems): void {
    this.selection.setLimits(modes, movable, this.store.state);
    this.requestRender();
  }

  /** Redraws everything from the store (after a refused drag left the drawing off the state). */
  private resync(): void {
    this.previous = null;
    this.update(this.store.state);
  }

  /** Before a frame: the camera's body hides when the view is inside it, and the outline follows a drag in progress. */
  private beforeDraw(): void {
    this.cameraScreen.setViewedFromEye(this.camera.position.distanceTo(this.cameraScreen.rig.position) < INSIDE_CAMERA);
    this.selection.followDrag(this.store.state);
  }

  /** After a frame: tells the probes what it showed, and the page how many rays it drew. */
  private drawn(): void {
    this.probes.frameDrawn(this.store.state.scene, this.screenRays?.scene ?? null);
    const thinning = this.drawing.rayLayer?.thinning ?? null;
    if (thinning?.shown !== this.drawnThinning?.shown || thinning?.of !== this.drawnThinning?.of || thinning?.oneSample !== this.drawnThinning?.oneSample) {
      this.drawnThinning = thinning;
      this.emit('thinning', thinning);
    }
    this.sceneJustLoaded = false;
  }

  /** Dispatches, showing the reason when the store refuses. Returns that reason. */
  private dispatch(action: LabAction): Issue[] | undefined {
    const error = this.store.dispatch(action);
    if (error) this.emit('message', error.map(issueText).join('\n'));
    return error;
  }

  private emit<K extends keyof LabViewEvents>(type: K, value: LabViewEvents[K]): void {
    for (const listener of this.listeners[type]) (listener as Listener<LabViewEvents[K]>)(value);
  }
}

const projected = new Vector3();

function sameCamera(a: LabState, b: LabState): boolean {
  const x = a.scene.camera;
  const y = b.scene.camera;
  return x.fov === y.fov && x.position.every((v, i) => v === y.position[i]) && x.target.every((v, i) => v === y.target[i]);
}
