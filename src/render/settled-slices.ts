import type { Scene } from '../scene/scene.ts';
import { countsEveryRay, tracedRays } from '../tracer/tree-budget.ts';
import { estimateRender } from './render-estimate.ts';
import type { ScreenRays } from './screen-rays.ts';

/**
 * About how many rays one slice of the settled screen holds: the full screen traced once the
 * edits stop (ScreenTracer.setBudget). With the free lab's largest settings that trace, 108,836
 * rays, went to the worker as one block: 0.3–0.6 s of tracing there, then as long again for
 * the page to take its rays in, and an edit arriving meanwhile waited for both before its
 * own trace could start (docs/benchmark-log.md). A slice of 4,096 rays is one or two of those
 * pixels (2,267 rays each): a few milliseconds of either side on a quiet machine.
 */
export const SLICE_RAYS = 4096;

/**
 * The sizes, in pixels, of the slices of `scene`'s settled screen, in screen order: as many
 * pixels as stay within SLICE_RAYS (at least one, at most `most`), counted by the rays each
 * pixel traced in `previous`, the last screen whose rays were all counted (a budget sends how
 * many it left out), or, for a screen of another size, by render-estimate.ts's guess for the scene.
 */
export function settledSlices(scene: Scene, previous: ScreenRays | null, most: number): number[] {
  const [columns, rows] = scene.camera.pixels;
  const pixels = columns * rows;
  const counted = previous !== null && previous.columns === columns && previous.rows === rows && countsEveryRay(previous.traces);
  const guess = estimateRender(scene, 1, 1).raysPerPixel;
  const sizes: number[] = [];
  let size = 0;
  let rays = 0;
  for (let p = 0; p < pixels; p++) {
    const pixelRays = counted ? tracedRays([previous.traces[p]]) : guess;
    if (size > 0 && (size === most || rays + pixelRays > SLICE_RAYS)) {
      sizes.push(size);
      size = 0;
      rays = 0;
    }
    size++;
    rays += pixelRays;
  }
  if (size > 0) sizes.push(size);
  return sizes;
}
