import type { PixelTrace } from '../tracer/ray-tree.ts';
import type { Scene } from '../scene/scene.ts';

/**
 * The ray trees of every pixel of the camera's screen, traced off the main thread for one
 * version of the scene (see ScreenTracer). `traces[y * columns + x]` is pixel (x, y).
 */
export interface ScreenRays {
  columns: number;
  rows: number;
  traces: PixelTrace[];
  /** The scene they were traced in (the screen tracer's; a test's screen may leave it out): what a drawn frame shows rays of. */
  scene?: Scene;
}
