import { Vector3 } from 'three';
import type { RayStats } from './ray-tree.ts';
import { addPathSamples } from './render-path-pixel.ts';
import { traceTile } from './render-tile.ts';
import type { RenderTileOptions, Tile } from './tile.ts';
import type { TracerScene } from './tracer-scene.ts';

const sum = new Vector3();

/**
 * One tile of a progressive pass in path mode: each pixel's sum of its paths so far
 * (`pathSums`, 3 values per pixel, row-major over the tile) carried on with paths
 * `firstPath` … `firstPath + samplesPerPixel` − 1, in 64-bit floats as a one-pass render
 * sums them (render-path-pixel.ts). The render window shows each sum divided by the paths
 * it holds; after the last pass that is the one-pass image to the bit.
 */
export function renderPathTile(scene: TracerScene, tile: Tile, options: RenderTileOptions, stats?: RayStats): Float64Array<ArrayBuffer> {
  const { imageWidth, imageHeight, seed, firstPath = 0, samplesPerPixel = scene.settings.pathSamples } = options;
  const sums = new Float64Array(tile.width * tile.height * 3);
  if (options.pathSums) sums.set(options.pathSums);
  traceTile(scene, tile, options, 1, stats, () => {
    for (let y = 0, i = 0; y < tile.height; y++) {
      for (let x = 0; x < tile.width; x++, i += 3) {
        sum.set(sums[i], sums[i + 1], sums[i + 2]);
        addPathSamples(scene, tile.x + x, tile.y + y, imageWidth, imageHeight, seed, firstPath, firstPath + samplesPerPixel, sum);
        sums[i] = sum.x;
        sums[i + 1] = sum.y;
        sums[i + 2] = sum.z;
      }
    }
  });
  return sums;
}
