/**
 * Which sweeps over the image a render makes (coarse previews, then full quality) and how big
 * their tiles are.
 *
 * A worker cannot stop inside a tile, so a tile's time bounds how soon a new render takes
 * over from the old one: the goal is well under 50 ms. Smaller tiles also share the last
 * tiles of an image better between workers; larger tiles cost fewer messages (about 0.1 ms
 * each, hidden by keeping two tiles in flight). A fixed size cannot serve both ends of the
 * lab's sliders (8×8 supersampling with a 10×10 area light costs 2000 times more per pixel
 * than the default scene), so the tile side follows an estimate of the rays per pixel.
 * Measured with two worker threads: the slowest tile took 4 ms (default scene), 4 ms (2×2
 * samples), 3 ms (plus a 4×4 area light) and 22 ms (8×8 samples, 10×10 area light: 1-pixel
 * tiles); a new render's first tile arrived 1–13 ms after it started.
 */
import { primaryRaysPerSample } from './render-estimate.ts';
import type { Scene } from '../scene/scene.ts';

export interface RenderPass {
  /** 1 = full quality; n > 1 = one traced pixel (one sample) per n×n block. */
  block: number;
  /** Side of the pass's square tiles in pixels, a multiple of `block`. */
  tileSide: number;
}

/**
 * Coarse passes before full quality: one traced pixel per 8×8 block, then per 4×4. Together
 * they cost 1/64 + 1/16 ≈ 8% of a one-sample full pass and show a picture within milliseconds.
 */
export const PREVIEW_BLOCKS = [8, 4];

/**
 * Rays one tile should cost: a 32×32 tile of the default scene (one sample, two lights, so
 * about 3 rays per pixel before mirrors and glass) measured 0.8 ms on average and 5 ms at the
 * slowest (Node 20, one worker thread per core).
 */
const RAYS_PER_TILE = 32 * 32 * 3;

/** Larger tiles save too few messages to matter and make the slowest tiles slower. */
const MAX_TILE_SIDE = 32;

export function planPasses(scene: Scene, preview: boolean): RenderPass[] {
  // Each lens and time ray of a sample is a primary ray with its own shadow rays.
  const raysPerSample = (1 + shadowRaysPerHit(scene)) * primaryRaysPerSample(scene);
  const samples = scene.settings.supersampling ** 2;
  const full: RenderPass = { block: 1, tileSide: tileSide(raysPerSample * samples) };
  if (!preview) return [full];
  // A preview traces one sample per block, so its tile covers block² times the pixels.
  return [...PREVIEW_BLOCKS.map((block) => ({ block, tileSide: tileSide(raysPerSample) * block })), full];
}

/** One per point or spot light, n² per n×n area light (counted even with shadows off: the
 *  light is still sampled n² times). */
function shadowRaysPerHit({ lights, settings }: Scene): number {
  return lights
    .filter((light) => settings.lightTypes[light.type])
    .reduce((rays, light) => rays + (light.type === 'area' ? light.samples ** 2 : 1), 0);
}

function tileSide(raysPerPixel: number): number {
  return Math.max(1, Math.min(MAX_TILE_SIDE, Math.floor(Math.sqrt(RAYS_PER_TILE / raysPerPixel))));
}
