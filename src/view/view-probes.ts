import type { Object3D, PerspectiveCamera, Scene as ThreeScene, WebGLRenderer } from 'three';
import type { Scene, Vec3 } from '../scene/scene.ts';
import { followRayPath } from '../tracer/ray-path.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import { hiddenFrom, rayEvidence, type EvidencePoint } from './ray-evidence.ts';
import type { RayLayer } from './ray-layer.ts';
import { rayColorKey, type RayColorKey } from './ray-palette.ts';

/** How much (sum over RGB, 0–765) drawing the rays must change a pixel for rayCoverage to count it. */
const COVERAGE_CHANGE = 24;

/** What the probes read of the 3D view (LabView gives them these). */
export interface ProbedView {
  readonly renderer: WebGLRenderer;
  readonly scene: ThreeScene;
  readonly camera: PerspectiveCamera;
  /** The drawn rays, or null. */
  rayLayer(): RayLayer | null;
  /** A code lab's failing case (case-overlay.ts), hidden when none is shown. */
  readonly caseLayer: Object3D;
  /** Whether the last frame showed every instance of the ray layer (piecewise-rays.ts). */
  allRaysDrawn(): boolean;
  /** Whether no frame is coming until something changes (frame-scheduler.ts). */
  idle(): boolean;
  /** Pixel `pixel`'s latest trace, chosen or not (null before it is traced). */
  traceOf(pixel: readonly [number, number]): PixelTrace | null;
  /** The world points a declared view fits for `name` (view-look.ts). */
  framedPointsOf(name: string): Vec3[];
  /** Where a world point appears on the canvas (CSS px from its top-left), or null behind the eye. */
  projectToView(point: Vec3): { x: number; y: number } | null;
  /** The drawn objects, which hide what is behind them from the eye. */
  readonly opaque: Object3D;
  requestRender(): void;
}

/**
 * For browser tests and tools (e2e/, scripts/): what the 3D view shows, read off it. Reached
 * as rt-scene-view's `labView.probes`. They live here, not in LabView, so that the view's
 * class holds only what the lab uses; the view tells them of each frame it draws
 * (frameDrawn) and they read the rest when asked.
 */
export class ViewProbes {
  private raysScene: Scene | null = null;
  private scene: Scene | null = null;

  constructor(private readonly view: ProbedView) {}

  /** Called by the view after each frame it draws anew: the scene it showed and the scene its traced rays are of. */
  frameDrawn(scene: Scene, raysScene: Scene | null): void {
    this.raysScene = raysScene;
    this.scene = scene;
  }

  /** The scene whose traced rays the last drawn frame showed (null before any), so a browser test can time a slider step to its rays on screen. */
  get drawnRaysScene(): Scene | null {
    return this.raysScene;
  }

  /** The scene the last drawn frame showed (its objects, lights and camera), null before any. */
  get drawnScene(): Scene | null {
    return this.scene;
  }

  /** Whether the last frame showed every instance of the ray layer (on a CPU rasterizer a heavy layer takes a piece a frame: piecewise-rays.ts). */
  get raysComplete(): boolean {
    return this.view.allRaysDrawn();
  }

  /**
   * Whether the view draws no frame until something changes: none scheduled or held. A test
   * of what costs a frame waits for this, as a frame asked for may wait seconds on SwiftShader
   * (FrameScheduler.idle).
   */
  get idle(): boolean {
    return this.view.idle();
  }

  /** Where the things a declared view frames appear on the canvas (CSS px): the points `frame` fits for `name` (view-look.ts), each projected (null behind the eye). */
  projectedPointsOf(name: string): ({ x: number; y: number } | null)[] {
    return this.view.framedPointsOf(name).map((point) => this.view.projectToView(point));
  }

  /**
   * The ray `path` names (tracer/ray-path.ts) in pixel `pixel`'s latest trace, chosen or not,
   * as the legend entry it is drawn as and points along it on the canvas, each hidden or not
   * behind an opaque object (ray-evidence.ts); null without such a ray.
   */
  evidenceRay(pixel: readonly [number, number], path: string): { drawnAs: RayColorKey; points: EvidencePoint[] } | null {
    const trace = this.view.traceOf(pixel);
    const node = trace ? followRayPath(trace, path) : null;
    if (!node) return null;
    const points = rayEvidence(
      node,
      (point) => this.view.projectToView(point),
      (point) => hiddenFrom(this.view.camera.position, point, [this.view.opaque]),
    );
    return { drawnAs: rayColorKey(node.type, node.hit, node.untested), points };
  }

  /**
   * Where the drawn rays show, as one byte per CSS pixel of the canvas (1 where drawing the
   * rays changed the picture), from a frame drawn now with them and one without: what is
   * covered or off screen counts as not shown.
   */
  rayCoverage(): { width: number; height: number; mask: Uint8Array } {
    return this.coverage(this.view.rayLayer()?.object ?? null);
  }

  /** Where a code lab's failing case shows, as rayCoverage does for the rays: all 0 when no case is drawn. */
  caseCoverage(): { width: number; height: number; mask: Uint8Array } {
    const layer = this.view.caseLayer;
    return layer.visible ? this.coverage(layer) : this.coverage(null);
  }

  /** Which CSS pixels drawing `layer` changes, from a frame with it and one without. */
  private coverage(layer: Object3D | null): { width: number; height: number; mask: Uint8Array } {
    const { renderer, scene, camera } = this.view;
    const gl = renderer.getContext();
    const width = gl.drawingBufferWidth;
    const height = gl.drawingBufferHeight;
    const frames = [true, false].map((shown) => {
      if (layer) layer.visible = shown;
      renderer.render(scene, camera);
      const pixels = new Uint8Array(width * height * 4);
      gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      return pixels;
    });
    if (layer) layer.visible = true;
    this.view.requestRender();
    const ratio = renderer.getPixelRatio();
    const cssWidth = Math.round(width / ratio);
    const cssHeight = Math.round(height / ratio);
    const mask = new Uint8Array(cssWidth * cssHeight);
    for (let y = 0; y < cssHeight; y++) {
      for (let x = 0; x < cssWidth; x++) {
        // readPixels rows run bottom-up.
        const i = ((height - 1 - Math.floor(y * ratio)) * width + Math.floor(x * ratio)) * 4;
        const change =
          Math.abs(frames[0]![i]! - frames[1]![i]!) + Math.abs(frames[0]![i + 1]! - frames[1]![i + 1]!) + Math.abs(frames[0]![i + 2]! - frames[1]![i + 2]!);
        mask[y * cssWidth + x] = change > COVERAGE_CHANGE ? 1 : 0;
      }
    }
    return { width: cssWidth, height: cssHeight, mask };
  }
}
