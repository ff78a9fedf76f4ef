import { LinearSRGBColorSpace, type Object3D, PerspectiveCamera, Scene as ThreeScene, Vector2, WebGLRenderer } from 'three';
import { BURST_SCALE, BurstResolution, HEAVY_BURST_SCALE } from './burst-resolution.ts';
import { tracesOneSample } from './ray-budget.ts';
import { type Animator, FrameScheduler } from './frame-scheduler.ts';
import { PiecewiseRays } from './piecewise-rays.ts';
import type { RayLayer } from './ray-layer.ts';
import { drawsInSoftware } from './software-renderer.ts';

/** The 3D view's own vertical field of view (degrees), which declared views frame with. */
export const VIEW_FOV = 45;

/**
 * How long the view waits after an edit of the scene for the edit's rays, before it draws
 * the edit without them. On a CPU rasterizer a frame costs about 50 ms, and the main thread
 * waits most of it for the 3D view's read-back: drawing the edit at once made its rays, back
 * from the screen tracer 10–20 ms later, wait for a second frame. Held until they come, one
 * frame shows both: in five e2e runs with the page composited on the CPU, an arrow key's
 * step went from p95 95–106 to 71–84 ms, a drag's from 64–98 to 64–68 ms and the first
 * drag's from 103–134 to 62–72 ms (docs/benchmark-log.md). A 16 × 16 screen takes about 15 ms
 * to trace; a bigger one is drawn after this wait, and its rays when they come.
 */
const RAYS_WAIT_MS = 60;

/** What the lab view does around each frame drawn anew (not around a further piece of the same picture). */
export interface DrawHooks {
  /** Just before the frame is drawn: last changes that follow the camera or a drag. */
  beforeDraw(): void;
  /** Just after: what the frame showed. */
  drawn(): void;
  /** The canvas got its first real size: a framing made for a guessed shape can be made again. */
  firstSized(): void;
}

/**
 * When and how the 3D view is drawn: the WebGL renderer with its three.js scene and the
 * user's camera, frames on demand (frame-scheduler.ts), the canvas's size and resolution,
 * and on a CPU rasterizer the coarse bursts (burst-resolution.ts) and the heavy ray layer
 * drawn a piece a frame (piecewise-rays.ts). Apart from LabView, which decides what is in
 * the scene, so that the costs of drawing and their figures sit in one place.
 */
export class ViewDrawing {
  readonly renderer: WebGLRenderer;
  readonly scene = new ThreeScene();
  /** The user's viewpoint (not the ray tracer's camera). */
  readonly camera = new PerspectiveCamera(VIEW_FOV, 1, 0.05, 500);
  readonly scheduler: FrameScheduler;
  /** WebGL draws on a CPU rasterizer (SwiftShader, llvmpipe): no antialiasing, bursts drawn coarse, rays held to a budget while the learner edits (LabServices). */
  readonly software: boolean;
  /** On a CPU rasterizer: a burst of edits is drawn at reduced resolution (null on a GPU). */
  private readonly burst: BurstResolution | null;
  /** On a CPU rasterizer: a heavy ray layer is drawn a piece a frame (null on a GPU). */
  private readonly pieces: PiecewiseRays | null;
  /** The share of the device pixel ratio drawn now (below 1 during a burst). */
  private resolutionScale = 1;
  private sized = false;
  private frames = 0;
  private layer: RayLayer | null = null;
  /** Whether the drawn rays stand aside for a drawing that must read on its own (setRaysAside). */
  private raysAside = false;
  private removeRayAnimator: (() => void) | null = null;
  private bvh: Object3D | null = null;

  constructor(
    canvas: HTMLCanvasElement,
    private readonly hooks: DrawHooks,
  ) {
    this.software = drawsInSoftware();
    this.renderer = new WebGLRenderer({ canvas, antialias: !this.software, alpha: true });
    this.burst = this.software ? new BurstResolution((scale) => this.setResolutionScale(scale)) : null;
    this.renderer.outputColorSpace = LinearSRGBColorSpace;
    this.renderer.setClearColor(0x000000, 0);
    this.pieces = this.software ? new PiecewiseRays(this.renderer) : null;
    this.scheduler = new FrameScheduler((changed) => this.draw(changed));
  }

  /** How many frames were drawn so far (idle means it stops growing). */
  get frameCount(): number {
    return this.frames;
  }

  /** Whether the last frame showed every instance of the ray layer (piecewise-rays.ts). */
  get allRaysDrawn(): boolean {
    return !this.pieces?.unfinished;
  }

  /** The drawn rays, or null (also while they stand aside: none are drawn, hovered or counted). */
  get rayLayer(): RayLayer | null {
    return this.raysAside ? null : this.layer;
  }

  /** The acceleration boxes shown, or null. */
  get bvhLayer(): Object3D | null {
    return this.bvh;
  }

  /** Draws one frame soon (call after changing anything drawn, like the ray layer's content). */
  requestRender(): void {
    this.scheduler.requestRender();
  }

  /** Calls `animator` every frame; frames keep coming while it returns true. Returns its remover. */
  addAnimator(animator: Animator): () => void {
    return this.scheduler.addAnimator(animator);
  }

  /** The canvas's size in CSS pixels; drawn at up to 2 device pixels per CSS pixel (school laptops). */
  setSize(width: number, height: number): void {
    if (width <= 0 || height <= 0) return;
    this.renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1) * this.resolutionScale);
    this.renderer.setSize(width, height, false);
    const first = !this.sized;
    this.sized = true;
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    if (first) this.hooks.firstSized();
    // A resized canvas is blank until drawn: draw now, not next frame, so it never flickers.
    this.scheduler.renderNow();
  }

  /** Draws at `scale` × the device pixel ratio from now on (redrawn at once). */
  private setResolutionScale(scale: number): void {
    this.resolutionScale = scale;
    if (!this.sized) return;
    // The renderer keeps the size last set in CSS pixels.
    const { x: width, y: height } = this.renderer.getSize(cssSize);
    this.setSize(width, height);
  }

  /** The scene was edited: a burst may start, and the frame waits a little for the edit's rays. */
  sceneEdited(): void {
    this.burst?.edited();
    // Rays held to a budget are a heavy screen's, traced in the worker for longer than the wait.
    if (!this.burst?.holding) this.scheduler.holdFor(RAYS_WAIT_MS);
  }

  /** New traced rays are in: draws them, in the frame an edit's hold waited for. */
  raysArrived(): void {
    this.requestRender();
    // After asking for the frame: the rays an edit's hold waited for are drawn in it, and the
    // next edit's hold does not delay it.
    this.scheduler.release();
  }

  /** Shows the drawn rays (replacing any before) and animates them. */
  setRayLayer(layer: RayLayer | null): void {
    if (this.layer) this.scene.remove(this.layer.object);
    this.removeRayAnimator?.();
    this.removeRayAnimator = null;
    this.layer = layer;
    if (layer) {
      layer.object.visible = !this.raysAside;
      this.scene.add(layer.object);
      this.removeRayAnimator = this.scheduler.addAnimator((time) => layer.tick(time));
    }
    this.requestRender();
  }

  /**
   * Hides the drawn rays (`aside`) while something drawn over the scene must read on its own,
   * a code lab's failing case: hundreds of the scene's rays cross its few; false shows them again.
   */
  setRaysAside(aside: boolean): void {
    if (aside === this.raysAside) return;
    this.raysAside = aside;
    if (this.layer) this.layer.object.visible = !aside;
    this.requestRender();
  }

  /**
   * On a CPU rasterizer: draws coarse while the drawn rays are thinned to `budget`, coarser for
   * a heavy screen's budget (tracesOneSample), sharp at once after (null).
   */
  holdCoarse(budget: number | null): void {
    this.burst?.hold(budget === null ? null : tracesOneSample(budget) ? HEAVY_BURST_SCALE : BURST_SCALE);
  }

  /** Shows the acceleration boxes (BvhBoxes.object), replacing any before; null removes them. */
  setBvhLayer(object: Object3D | null): void {
    if (this.bvh) this.scene.remove(this.bvh);
    this.bvh = object;
    if (object) this.scene.add(object);
    this.requestRender();
  }

  private draw(changed: boolean): void {
    const layer = this.rayLayer;
    if (!changed && this.pieces?.unfinished && layer) {
      this.pieces.drawNext(this.camera, layer);
      if (this.pieces.unfinished) this.scheduler.requestMore();
      this.frames++;
      return;
    }
    this.hooks.beforeDraw();
    if (this.pieces) {
      this.pieces.drawChanged(this.scene, this.camera, layer);
      if (this.pieces.unfinished) this.scheduler.requestMore();
    } else this.renderer.render(this.scene, this.camera);
    this.hooks.drawn();
    this.frames++;
  }

  /** Draws no more frames: first when the view goes, before the scene's parts are disposed. */
  stop(): void {
    this.removeRayAnimator?.();
    if (this.layer) this.scene.remove(this.layer.object);
    this.burst?.dispose();
    this.pieces?.dispose();
    this.scheduler.dispose();
  }

  /** Frees the WebGL context: last, after everything drawn with it. */
  dispose(): void {
    this.renderer.dispose();
  }
}

/** Scratch for the canvas size read back from the renderer. */
const cssSize = new Vector2();
