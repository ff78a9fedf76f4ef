import { Vector3 } from 'three';
import type { Color } from '../scene/scene.ts';
import { PathRecorder, type RecordedPath } from './path-recorder.ts';
import { renderPathPixel } from './render-path-pixel.ts';
import type { TracerScene } from './tracer-scene.ts';

/** A pixel's paths in path mode (`rt trace --paths`): its colour, and its first paths. */
export interface PixelPaths {
  pixel: [number, number];
  /** The mean of all the pixel's paths: that pixel of an image of camera.pixels rendered with the same seed (as 32-bit floats, as the image stores it). */
  color: Color;
  /** How many paths the pixel averaged (settings.pathSamples). */
  pathCount: number;
  paths: RecordedPath[];
}

/**
 * The paths of pixel (px, py) of the camera's screen (`camera.pixels` resolution), re-created
 * exactly as the image traced them (path-tracing spec §3): the first `keep` of them, and the
 * pixel's colour, which the mean of all their contributions is to the last bit.
 */
export function tracePaths(scene: TracerScene, px: number, py: number, seed: number, keep = Infinity): PixelPaths {
  const [width, height] = scene.source.camera.pixels;
  const recorder = new PathRecorder();
  const color = renderPathPixel(scene, px, py, width, height, seed, new Vector3(), recorder);
  return {
    pixel: [px, py],
    color: [Math.fround(color.x), Math.fround(color.y), Math.fround(color.z)],
    pathCount: recorder.paths.length,
    paths: recorder.paths.slice(0, keep),
  };
}
