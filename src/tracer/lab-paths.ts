import type { Color } from '../scene/scene.ts';
import { tracePaths, type PixelPaths } from './trace-paths.ts';
import type { TracerScene } from './tracer-scene.ts';
import { LAB_PATH_COUNT } from './lab-path-count.ts';

/**
 * A pixel's paths for the lab (the 3D view and the ray debugger): the first `keep` paths with
 * every vertex, and what each of all the pixel's paths added, so the debugger can show the
 * pixel as the mean of them all, whatever `keep` is.
 */
export interface LabPaths extends PixelPaths {
  /** Every path's contribution, in sample order (pathCount of them). */
  contributions: Color[];
}

/** Pixel (px, py)'s paths, re-created exactly as the image traced them (trace-paths.ts). */
export function labPaths(scene: TracerScene, px: number, py: number, seed: number, keep = LAB_PATH_COUNT): LabPaths {
  const all = tracePaths(scene, px, py, seed);
  return { ...all, paths: all.paths.slice(0, keep), contributions: all.paths.map((path) => path.contribution) };
}
