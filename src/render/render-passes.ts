/**
 * Which sweeps over the image a render makes and how big their tiles are: coarse previews,
 * then a sharp one-sample picture, then full quality (issue: tracer speed, "what the user
 * waits for").
 *
 * - **Coarse previews** trace one sample per block×block square and fill the square. The
 *   first block is the finest power of two (from 8 up) whose pass the render estimate puts
 *   under FIRST_PASS_SECONDS, so even the heaviest scene the schema accepts has a whole
 *   picture, and a moving progress bar, within the first second; each next pass halves the
 *   block, down to 4. Each costs a quarter of the next, so all previews together cost about
 *   8 % of the sharp pass (1/16 + 1/64 + …).
 * - **The sharp pass** traces one sample per pixel (placed as the previews' samples are). With
 *   s×s supersampling the final pass costs s² times as much, so a sharp picture appears
 *   after about 1/s² of the final time; without supersampling the final pass is that picture
 *   and the sharp pass is left out.
 * - **The final pass** traces every pixel at the scene's supersampling: the image.
 * - **Path mode** (path-passes.ts) follows the previews with passes of one path per pixel (or
 *   a few), each added to the pixels' sums: every one of them is a final pass.
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
 * A render without previews (`rt render`) has nobody waiting on its tiles: they carry four
 * times the rays (RAYS_PER_UNWATCHED_TILE).
 */
import type { Scene } from '../scene/scene.ts';
import type { Tile } from '../tracer/tile.ts';
import { pathPasses, pathsPerPass, refinesPaths } from './path-passes.ts';
import { primaryRaysPerSample, RAYS_PER_SECOND_PER_WORKER, raysPerSample, samplesPerPixel, shadowRaysPerHit } from './render-estimate.ts';

/** What a pass makes: coarse blocks, one sample per pixel, or the finished image. */
export type PassKind = 'preview' | 'sharp' | 'final';

export interface RenderPass {
  kind: PassKind;
  /** 1, or n > 1 for one traced sample per n×n block (a preview). */
  block: number;
  /** Samples of each traced pixel: the scene's (s² or path mode's N) in the final pass, else 1. */
  samplesPerPixel: number;
  /** The pass's tiles in pixels, multiples of `block` (the image's edges cut the last ones). */
  tileWidth: number;
  tileHeight: number;
  /** Path mode's progressive passes (path-passes.ts): the pass adds paths firstPath … firstPath + samplesPerPixel − 1 to every pixel's sum. */
  firstPath?: number;
}

export interface PassPlanOptions {
  width: number;
  height: number;
  /** Workers sharing the render: more of them make a finer first preview affordable. */
  workers: number;
  /** Previews and the sharp pass before the final one (the render window); `rt render` turns them off. */
  preview: boolean;
  /** One pass of one sample per pixel, whatever the supersampling: the estimate's probe of what a sample costs (render-probe.ts). */
  oneSample?: boolean;
}

/** The render estimate's time for the first preview pass: the "first second" with a wide margin. */
export const FIRST_PASS_SECONDS = 0.25;

/** The finest preview block, and the first one tried (as before the first pass adapted). */
const FINEST_PREVIEW_BLOCK = 4;
const FIRST_PREVIEW_BLOCK = 8;

/**
 * Rays one tile should cost: a 32×32 tile of the default scene (one sample, two lights, so
 * about 3 rays per pixel before mirrors and glass) measured 0.8 ms on average and 5 ms at the
 * slowest (Node 20, one worker thread per core).
 */
const RAYS_PER_TILE = 32 * 32 * 3;

/** Larger tiles save too few messages to matter and make the slowest tiles slower. */
const MAX_TILE_SIDE = 32;

/**
 * Rays a tile costs in a render without previews (`rt render`): nobody waits on one of its
 * tiles to cancel it or to see it, so they are sized for throughput. Every tile costs a
 * message each way (about 20 µs of a worker's time) and a fresh list of the objects its
 * primary rays can meet (primary-candidates.ts). The reference scene's 6 × 6 tiles spent
 * about 6 % of a worker's time in messages; with four times the rays (13 × 13 tiles there)
 * the 2-worker render took about 0.93× as long, and with 24 times (32 × 32, MAX_TILE_SIDE)
 * 0.95× as long again (7 alternating runs of 3 renders each, the same image to the bit).
 * The order of the pixels inside a tile is not what costs: rows alternating in direction
 * changed nothing (docs/benchmark-log.md, sixteenth round).
 */
const RAYS_PER_UNWATCHED_TILE = 24 * RAYS_PER_TILE;

export function planPasses(scene: Scene, { width, height, workers, preview, oneSample }: PassPlanOptions): RenderPass[] {
  // Each lens and time ray of a sample is a primary ray with its own shadow rays (distribution-effects §2).
  const oneSampleSide = tileSide((1 + shadowRaysPerHit(scene)) * primaryRaysPerSample(scene));
  if (oneSample) return [{ kind: 'final', block: 1, samplesPerPixel: 1, tileWidth: oneSampleSide, tileHeight: oneSampleSide }];
  const finalSide = finalTileSide(scene, preview);
  const final: RenderPass = { kind: 'final', block: 1, samplesPerPixel: samplesPerPixel(scene), tileWidth: finalSide, tileHeight: finalSide };
  if (!preview) return [final];
  const secondsPerSample = (raysPerSample(scene) * primaryRaysPerSample(scene)) / (RAYS_PER_SECOND_PER_WORKER * Math.max(1, workers));
  const passes: RenderPass[] = [];
  for (let block = firstBlock(width, height, secondsPerSample); block >= FINEST_PREVIEW_BLOCK; block /= 2) {
    passes.push({ kind: 'preview', block, samplesPerPixel: 1, ...previewTile(width, block, oneSampleSide ** 2) });
  }
  if (refinesPaths(scene, width, height, preview)) {
    const pathRays = raysPerSample(scene);
    return [...passes, ...pathPasses(scene.settings.pathSamples, pathsPerPass(scene, width, height, workers), (paths) => tileSide(pathRays * paths))];
  }
  if (final.samplesPerPixel > 1) passes.push({ kind: 'sharp', block: 1, samplesPerPixel: 1, tileWidth: oneSampleSide, tileHeight: oneSampleSide });
  passes.push(final);
  return passes;
}

/** The tile side of the final pass, after previews or without them (`rt render` counts its tiles to cap the workers). */
export function finalTileSide(scene: Scene, preview: boolean): number {
  const raysPerPixel = (1 + shadowRaysPerHit(scene)) * primaryRaysPerSample(scene) * samplesPerPixel(scene);
  return tileSide(raysPerPixel, preview ? RAYS_PER_TILE : RAYS_PER_UNWATCHED_TILE);
}

/** Samples a pass traces for `tile`: one per block (rows and columns cut by the edge count whole), s² per pixel in the final pass. */
export function tracedSamples({ width, height }: Tile, { block, samplesPerPixel }: Pick<RenderPass, 'block' | 'samplesPerPixel'>): number {
  return Math.ceil(width / block) * Math.ceil(height / block) * samplesPerPixel;
}

/**
 * A preview tile of `samples` traced samples (one per block), as whole rows of blocks where
 * a row has no more than that: the window repaints the rows a tile changed, so a square tile
 * had it repaint those rows across the whole image for each tile of the row (at 4096² most
 * of the page's time). A heavy scene's rows are cut into strips one block high.
 */
function previewTile(width: number, block: number, samples: number): Pick<RenderPass, 'tileWidth' | 'tileHeight'> {
  const blocksPerRow = Math.ceil(width / block);
  if (blocksPerRow > samples) return { tileWidth: samples * block, tileHeight: block };
  return { tileWidth: blocksPerRow * block, tileHeight: Math.floor(samples / blocksPerRow) * block };
}

/** The finest power-of-two block from FIRST_PREVIEW_BLOCK up whose pass fits FIRST_PASS_SECONDS; never beyond one block for the whole image. */
function firstBlock(width: number, height: number, secondsPerSample: number): number {
  let block = FIRST_PREVIEW_BLOCK;
  const passSeconds = () => Math.ceil(width / block) * Math.ceil(height / block) * secondsPerSample;
  while (block < Math.max(width, height) && passSeconds() > FIRST_PASS_SECONDS) block *= 2;
  return block;
}

function tileSide(raysPerPixel: number, raysPerTile = RAYS_PER_TILE): number {
  return Math.max(1, Math.min(MAX_TILE_SIDE, Math.floor(Math.sqrt(raysPerTile / raysPerPixel))));
}
