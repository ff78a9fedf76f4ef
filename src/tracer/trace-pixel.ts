import { Vector3 } from 'three';
import { assignContributions } from './ray-contributions.ts';
import { RayTreeRecording } from './ray-recorder.ts';
import type { PixelTrace } from './ray-tree.ts';
import { renderPixel } from './render-pixel.ts';
import type { TracerScene } from './tracer-scene.ts';

/** What a pixel's tree records besides its rays. */
export interface TraceOptions {
  /** Every hit's shading terms (ray-debugger spec §1); the rays and colours are the same without. */
  terms?: boolean;
}

/**
 * The ray tree of pixel (px, py) of the camera's screen (`camera.pixels` resolution): one
 * root per supersample. Its colour is exactly that pixel of an image rendered at that
 * resolution with the same seed (the image stores 32-bit floats, so the colour is rounded
 * to them too).
 */
export function tracePixel(scene: TracerScene, px: number, py: number, seed: number, options: TraceOptions = {}): PixelTrace {
  const [width, height] = scene.source.camera.pixels;
  const tree = new RayTreeRecording(options.terms === true);
  const color = renderPixel(scene, px, py, width, height, seed, new Vector3(), tree);
  const roots = tree.roots;
  assignContributions(roots, tree.weights, tree.unclampedSums);
  if (options.terms) {
    for (const root of roots) root.weight = 1 / roots.length;
    for (const [node, weight] of tree.weights) node.weight = weight;
  }
  return { pixel: [px, py], color: [Math.fround(color.x), Math.fround(color.y), Math.fround(color.z)], rays: roots };
}

/**
 * Pixels `first` … `first + count - 1` of the camera's screen (row-major over
 * `camera.pixels`), each as tracePixel gives it: the lab's screen, whether a worker traces it
 * in blocks or the main thread traces it whole.
 */
export function tracePixels(scene: TracerScene, first: number, count: number, seed: number): PixelTrace[] {
  const columns = scene.source.camera.pixels[0];
  const traces = new Array<PixelTrace>(count);
  for (let i = 0; i < count; i++) traces[i] = tracePixel(scene, (first + i) % columns, Math.floor((first + i) / columns), seed);
  return traces;
}
