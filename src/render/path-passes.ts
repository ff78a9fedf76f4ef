/**
 * Path mode's progressive passes (path-tracing spec §4: "the render window refines
 * progressively, one path per pixel per pass, and shows the sample count so far"). After the
 * coarse previews, every pass traces the next path (or next few paths) of every pixel and
 * adds it to the pixel's running sum; the window shows each sum over the paths it holds, a
 * picture whose noise falls pass after pass, as 1/√(paths so far). The sums are carried on
 * in the order one pass over all N paths adds them, so the last pass's picture is the
 * one-pass render (`rt render`) to the bit (render-path-tile.ts).
 */
import type { Scene } from '../scene/scene.ts';
import { RAYS_PER_SECOND_PER_WORKER, raysPerSample } from './render-estimate.ts';
import type { RenderPass } from './render-passes.ts';

/**
 * The pool keeps each pixel's sums in 64-bit floats, 24 bytes a pixel on top of the picture:
 * a larger image (over 96 MB of sums) renders its paths in one final pass after a sharp one.
 */
export const MAX_PROGRESSIVE_PIXELS = 2048 * 2048;

/**
 * A pass should take at least this long by the render estimate: below it a small image
 * would be repainted (and its tiles messaged) far more often than the eye follows. The
 * estimate counts every path at full length, so passes really take a third to a half of it.
 */
const MIN_PATH_PASS_SECONDS = 0.1;

/** At most this many passes: a render of 65 536 paths per pixel adds 256 at a time. */
const MAX_PATH_PASSES = 256;

/** Whether a render of `scene` at this size refines its paths pass after pass. */
export function refinesPaths(scene: Scene, width: number, height: number, preview: boolean): boolean {
  return preview && scene.settings.integrator === 'path' && width * height <= MAX_PROGRESSIVE_PIXELS;
}

/** Paths per pixel each pass adds: one, unless a pass of one would be shorter than MIN_PATH_PASS_SECONDS or there would be over MAX_PATH_PASSES. */
export function pathsPerPass(scene: Scene, width: number, height: number, workers: number): number {
  const paths = scene.settings.pathSamples;
  const onePathSeconds = (width * height * raysPerSample(scene)) / (RAYS_PER_SECOND_PER_WORKER * Math.max(1, workers));
  const forTime = Math.ceil(MIN_PATH_PASS_SECONDS / Math.max(onePathSeconds, Number.MIN_VALUE));
  return Math.min(paths, Math.max(1, forTime, Math.ceil(paths / MAX_PATH_PASSES)));
}

/** The passes of paths [0, N), `perPass` at a time (the last may hold fewer), in tiles of `tileSide(paths)` a side. */
export function pathPasses(paths: number, perPass: number, tileSide: (pathsInPass: number) => number): RenderPass[] {
  const passes: RenderPass[] = [];
  for (let firstPath = 0; firstPath < paths; firstPath += perPass) {
    const samplesPerPixel = Math.min(perPass, paths - firstPath);
    const side = tileSide(samplesPerPixel);
    passes.push({ kind: 'final', block: 1, samplesPerPixel, firstPath, tileWidth: side, tileHeight: side });
  }
  return passes;
}
