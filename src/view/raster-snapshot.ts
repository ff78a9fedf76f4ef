import { Color, type Object3D, PerspectiveCamera, type Scene as ThreeScene, type WebGLRenderer, WebGLRenderTarget } from 'three';
import type { Camera, Color as RgbColor } from '../scene/scene.ts';

/**
 * The raster view as the ray tracer's camera sees it (same eye, target and vertical fov, the
 * aspect of width/height), rendered off screen and read back, for the render window's
 * side-by-side comparison. The on-screen canvas is not touched: the frame goes to a render
 * target, and everything hidden for it (gizmos, rays, the screen) is shown again after.
 *
 * The frame is drawn at once (the scene as it is now) and read back asynchronously (a pixel
 * buffer and a fence): a synchronous read waits on the GPU, which blocked the page for
 * seconds on a software GPU at 4096 × 4096.
 *
 * @param hidden parts of the lab that are not part of the scene (helpers, gizmos, rays)
 * @param background the tracer's background colour, so both images share it
 * @param samples multisampling, as the on-screen view antialiases: 4 on a GPU, 0 on a CPU
 *   rasterizer, where a 1024² frame at 4 samples kept the GPU process busy about 330 ms and
 *   the page froze that long after Render was clicked (its next commit waits for the GPU)
 */
export async function rasterSnapshot(
  renderer: WebGLRenderer,
  scene: ThreeScene,
  hidden: readonly Object3D[],
  camera: Camera,
  background: RgbColor,
  width: number,
  height: number,
  samples: number,
): Promise<ImageData> {
  const view = new PerspectiveCamera(camera.fov, width / height, 0.01, 1000);
  view.position.set(...camera.position);
  // Looking straight up or down, +Y cannot be "up": use ∓Z as CameraRays does.
  const dx = camera.target[0] - camera.position[0];
  const dy = camera.target[1] - camera.position[1];
  const dz = camera.target[2] - camera.position[2];
  if (Math.abs(dy) > 0.999 * Math.hypot(dx, dy, dz)) view.up.set(0, 0, -Math.sign(dy));
  view.lookAt(...camera.target);
  view.updateMatrixWorld();

  const target = new WebGLRenderTarget(width, height, { samples });
  const wasVisible = hidden.map((object) => object.visible);
  const previousBackground = scene.background;
  const previousTarget = renderer.getRenderTarget();
  const pixels = new Uint8Array(width * height * 4);
  try {
    for (const object of hidden) object.visible = false;
    scene.background = new Color().setRGB(...background);
    renderer.setRenderTarget(target);
    renderer.clear();
    renderer.render(scene, view);
  } catch (error) {
    target.dispose();
    throw error;
  } finally {
    hidden.forEach((object, i) => (object.visible = wasVisible[i]));
    scene.background = previousBackground;
    renderer.setRenderTarget(previousTarget);
  }
  try {
    await renderer.readRenderTargetPixelsAsync(target, 0, 0, width, height, pixels);
  } finally {
    target.dispose();
  }
  // WebGL reads rows bottom-up; images run top-down.
  const image = new ImageData(width, height);
  const row = width * 4;
  for (let y = 0; y < height; y++) image.data.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return image;
}
