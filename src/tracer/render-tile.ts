import { Vector3 } from 'three';
import type { RayStats } from './ray-tree.ts';
import { addRayStats } from './ray-tree.ts';
import { integratorFor, renderPixel } from './render-pixel.ts';
import type { RenderTileOptions, Tile } from './tile.ts';
import type { TracerScene } from './tracer-scene.ts';
import { PrimaryCandidates } from './primary-candidates.ts';

const color = new Vector3();
const primaryCandidates = new PrimaryCandidates();

/**
 * Renders one tile of the image: linear RGB, 3 floats per pixel, row-major over the tile,
 * each channel clamped to 0..1 in Whitted mode (path mode: radiance, unclamped). Ray counts
 * are added to `stats` when given.
 *
 * With `options.block` > 1 it is a coarse preview: the image is traced as if it were
 * block times smaller (one sample through each block's centre) and each block is filled.
 * `options.samplesPerPixel` 1 at block 1 traces one sample per pixel (the sharp pass).
 */
export function renderTile(scene: TracerScene, tile: Tile, options: RenderTileOptions, stats?: RayStats): Float32Array {
  const block = Math.max(1, Math.floor(options.block ?? 1));
  const rgb = new Float32Array(tile.width * tile.height * 3);
  traceTile(scene, tile, options, block, stats, () => renderPixels(scene, tile, options, block, rgb));
  return rgb;
}

/**
 * Runs `trace` over a tile of the image traced `block` times smaller: the integrator's pixel
 * spread and the objects the tile's primary rays can meet are set for it, and the rays it
 * traced are added to `stats` when given.
 */
export function traceTile(scene: TracerScene, tile: Tile, options: RenderTileOptions, block: number, stats: RayStats | undefined, trace: () => void): void {
  const { imageWidth, imageHeight } = options;
  const integrator = integratorFor(scene);
  // A preview traces an image `block` times smaller: its pixels are that much wider.
  integrator.pixelSpread = scene.camera.pixelSpread(imageHeight / block);
  integrator.stats.primary = integrator.stats.shadow = integrator.stats.reflect = integrator.stats.refract = 0;
  // The tile's primary rays, in the image traced (a preview's is block times smaller).
  integrator.primaryCandidates = primaryCandidates.set(
    scene,
    tile.x / block,
    tile.y / block,
    (tile.x + tile.width) / block,
    (tile.y + tile.height) / block,
    imageWidth / block,
    imageHeight / block,
  );
  try {
    trace();
  } finally {
    integrator.primaryCandidates = null;
  }
  if (stats) addRayStats(stats, integrator.stats);
}

function renderPixels(scene: TracerScene, tile: Tile, options: RenderTileOptions, block: number, rgb: Float32Array): void {
  const { imageWidth, imageHeight, seed } = options;
  const rowLength = tile.width * 3;
  for (let by = 0; by < tile.height; by += block) {
    for (let bx = 0; bx < tile.width; bx += block) {
      if (block === 1) renderPixel(scene, tile.x + bx, tile.y + by, imageWidth, imageHeight, seed, color, null, options.samplesPerPixel);
      else renderPixel(scene, (tile.x + bx) / block, (tile.y + by) / block, imageWidth / block, imageHeight / block, seed, color, null, 1);
      for (let i = by * rowLength + bx * 3, end = by * rowLength + Math.min(bx + block, tile.width) * 3; i < end; i += 3) {
        rgb[i] = color.x;
        rgb[i + 1] = color.y;
        rgb[i + 2] = color.z;
      }
    }
    // A block's other rows repeat its first: one copy per row, not a write per pixel (a
    // 4096² preview fills 16 M pixels whatever its block, which dominated its time).
    for (let y = by + 1; y < Math.min(by + block, tile.height); y++) rgb.copyWithin(y * rowLength, by * rowLength, (by + 1) * rowLength);
  }
}
