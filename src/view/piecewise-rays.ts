import {
  type Camera,
  Mesh,
  NearestFilter,
  NoBlending,
  type Object3D,
  OrthographicCamera,
  PlaneGeometry,
  RawShaderMaterial,
  Scene,
  Vector2,
  type WebGLRenderer,
  WebGLRenderTarget,
} from 'three';
import { EDIT_RAY_BUDGET } from './ray-budget.ts';
import type { RayLayer } from './ray-layer.ts';

/**
 * Instances (rays and cones) drawn per frame when a heavy ray layer is drawn over several
 * frames. On SwiftShader a sharp frame costs about 0.1 ms per drawn ray (three to four
 * times the coarse frame's 0.035 ms: docs/benchmark-log.md), so a piece of 400 adds
 * about 40 ms to a frame: an edit arriving meanwhile waits for at most that, where a frame of
 * all 108,836 rays of the free lab's largest settings held it for 6–7 s.
 */
export const PIECE_INSTANCES = 400;

/**
 * Draws a ray layer with more than EDIT_RAY_BUDGET instances over several frames, on a CPU
 * rasterizer: a changed frame draws the scene with the layer's first piece into a picture
 * of its own (a render target the size of the canvas's drawing buffer), each later frame adds
 * the next piece to that picture, and every frame copies the picture to the canvas. The GPU
 * then never gets a frame of more than a piece of rays, and the rays fill in a piece a frame
 * (progressive refinement, as interactive viewers do). The pieces are drawn in the layer's
 * own order with its own materials, after the rest of the scene (a screenshot of 7,522 rays
 * drawn so was the same to the byte as one frame of them). A layer within the budget, as
 * every level's own screens and an edit's thinned rays are, is drawn in one frame straight
 * to the canvas, as before.
 */
export class PiecewiseRays {
  private picture: WebGLRenderTarget | null = null;
  /** Instances of the layer in the picture so far, and in all. */
  private drawn = 0;
  private total = 0;
  private readonly copyScene = new Scene();
  private readonly copyCamera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
  private readonly copyMaterial = new RawShaderMaterial({
    uniforms: { picture: { value: null } },
    // The picture's pixels as they are: the canvas gets exactly what the frame drew into it.
    vertexShader: 'attribute vec3 position; attribute vec2 uv; varying vec2 vUv; void main() { vUv = uv; gl_Position = vec4(position.xy, 0.0, 1.0); }',
    fragmentShader: 'precision highp float; uniform sampler2D picture; varying vec2 vUv; void main() { gl_FragColor = texture2D(picture, vUv); }',
    blending: NoBlending,
    depthTest: false,
    depthWrite: false,
  });

  constructor(private readonly renderer: WebGLRenderer) {
    this.copyScene.add(new Mesh(new PlaneGeometry(2, 2), this.copyMaterial));
  }

  /** Whether the picture still lacks some of the layer's instances (draw `next` on the next frame). */
  get unfinished(): boolean {
    return this.drawn < this.total;
  }

  /** The layer's instances on the canvas now. */
  get onCanvas(): number {
    return this.drawn;
  }

  /** Draws a changed frame of `scene`: all of `layer` at once when within the budget, else its first piece. */
  drawChanged(scene: Object3D, camera: Camera, layer: RayLayer | null): void {
    this.total = layer?.instances ?? 0;
    if (!layer || this.total <= EDIT_RAY_BUDGET) {
      this.drawn = this.total;
      this.renderer.render(scene, camera);
      return;
    }
    layer.drawFirst(PIECE_INSTANCES);
    try {
      this.renderer.setRenderTarget(this.sizedPicture());
      this.renderer.render(scene, camera);
    } finally {
      this.renderer.setRenderTarget(null);
      // The layer draws all its instances again outside this frame (picking, coverage, stats).
      layer.drawFirst(null);
    }
    this.drawn = PIECE_INSTANCES;
    this.copyToCanvas();
  }

  /** Adds the next piece of `layer` to the picture and shows it; the camera and scene are those of the changed frame. */
  drawNext(camera: Camera, layer: RayLayer): void {
    const picture = this.picture;
    if (!picture || !this.unfinished) return;
    const count = Math.min(PIECE_INSTANCES, this.total - this.drawn);
    const autoClear = this.renderer.autoClear;
    this.renderer.autoClear = false;
    try {
      this.renderer.setRenderTarget(picture);
      this.renderer.render(layer.piece(this.drawn, count), camera);
    } finally {
      this.renderer.setRenderTarget(null);
      this.renderer.autoClear = autoClear;
    }
    this.drawn += count;
    this.copyToCanvas();
  }

  dispose(): void {
    this.picture?.dispose();
    this.copyMaterial.dispose();
    for (const child of this.copyScene.children) if (child instanceof Mesh) child.geometry.dispose();
  }

  /** The picture at the canvas's drawing-buffer size (made again when that changed). */
  private sizedPicture(): WebGLRenderTarget {
    const { x: width, y: height } = this.renderer.getDrawingBufferSize(bufferSize);
    if (!this.picture || this.picture.width !== width || this.picture.height !== height) {
      this.picture?.dispose();
      this.picture = new WebGLRenderTarget(width, height, { minFilter: NearestFilter, magFilter: NearestFilter, depthBuffer: true, generateMipmaps: false });
      this.copyMaterial.uniforms.picture.value = this.picture.texture;
    }
    return this.picture;
  }

  private copyToCanvas(): void {
    this.renderer.render(this.copyScene, this.copyCamera);
  }
}

const bufferSize = new Vector2();
