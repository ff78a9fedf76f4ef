import { Vector3 } from 'three';
import type { RayStats } from './ray-tree.ts';
import { addRayStats } from './ray-tree.ts';
import { integratorFor, renderPixel } from './render-pixel.ts';
import type { RenderTileOptions, Tile } from './tile.ts';
import type { TracerScene } from './tracer-scene.ts';

const color = new Vector3();

/**
 * Renders one tile of the image: linear RGB, 3 floats per pixel, row-major over the tile,
 * each channel clamped to 0..1. Ray counts are added to `stats` when given.
 *
 * With `options.block` > 1 it is a coarse preview: the image is traced as if it were
 * block times smaller (one sample through each block's centre) and each block is filled.
 * `options.samplesPerSide` 1 at block 1 traces one sample per pixel (the sharp pass).
 */
export function renderTile(scene: TracerScene, tile: Tile, options: RenderTileOptions, stats?: RayStats): Float32Array {
  const { imageWidth, imageHeight, seed } = options;
  const block = Math.max(1, Math.floor(options.block ?? 1));
  const rgb = new Float32Array(tile.width * tile.height * 3);
  const integrator = integratorFor(scene);
  integrator.stats.primary = integrator.stats.shadow = integrator.stats.reflect = integrator.stats.refract = 0;

  for (let by = 0; by < tile.height; by += block) {
    for (let bx = 0; bx < tile.width; bx += block) {
      if (block === 1) renderPixel(scene, tile.x + bx, tile.y + by, imageWidth, imageHeight, seed, color, null, options.samplesPerSide);
      else renderPixel(scene, (tile.x + bx) / block, (tile.y + by) / block, imageWidth / block, imageHeight / block, seed, color, null, 1);
      for (let y = by; y < Math.min(by + block, tile.height); y++) {
        for (let x = bx; x < Math.min(bx + block, tile.width); x++) color.toArray(rgb, (y * tile.width + x) * 3);
      }
    }
  }

  if (stats) addRayStats(stats, integrator.stats);
  return rgb;
}
