// Converged means of a few 8 × 8 blocks of a path-traced picture, for settling whether a block
// that disagrees with Cycles (../shared/anchors/cycles-cornell/compare.py) is biased or only
// noisy: rendering the whole picture with thousands of paths per pixel takes the machine for
// an hour, a handful of blocks a few minutes.
//   npx tsx bench/path-block-means.ts SCENE.json W H PATHS SEED BX,BY [BX,BY …]
// Each block is rendered with PATHS paths per pixel in 16 batches of paths (the tracer's own
// paths firstPath … of each pixel, as the render window's passes trace them), so the batch
// means give a standard error that does not trust any one render's noise estimate. Prints one
// JSON line per block: its mean RGB over the 64 pixels and the standard error of each channel.
import { readScene } from '../src/cli/scene-file.ts';
import { renderPathTile } from '../src/tracer/render-path-tile.ts';
import { buildTracerScene } from '../src/tracer/tracer-scene.ts';

const BLOCK = 8;
const BATCHES = 16;

const [file, w, h, paths, seed, ...blocks] = process.argv.slice(2);
if (!file || !w || !h || !paths || !seed || blocks.length === 0) {
  console.error('usage: npx tsx bench/path-block-means.ts SCENE.json W H PATHS SEED BX,BY [BX,BY …]');
  process.exit(2);
}
const [width, height, pathCount] = [Number(w), Number(h), Number(paths)];
if (pathCount % BATCHES !== 0) throw new Error(`PATHS must be a multiple of ${BATCHES}`);
const perBatch = pathCount / BATCHES;
const { scene } = await readScene(file);
const tracer = buildTracerScene({ ...scene, settings: { ...scene.settings, imageSize: [width, height] } }, new Map());

for (const block of blocks) {
  const [bx, by] = block.split(',').map(Number) as [number, number];
  const tile = { x: bx * BLOCK, y: by * BLOCK, width: BLOCK, height: BLOCK };
  const batchMeans: number[][] = [];
  for (let batch = 0; batch < BATCHES; batch++) {
    const options = { imageWidth: width, imageHeight: height, seed: Number(seed), firstPath: batch * perBatch, samplesPerPixel: perBatch };
    const sums = renderPathTile(tracer, tile, options);
    const mean = [0, 0, 0];
    for (let i = 0; i < sums.length; i++) mean[i % 3] += sums[i]! / (perBatch * BLOCK * BLOCK);
    batchMeans.push(mean);
  }
  const mean = [0, 1, 2].map((c) => batchMeans.reduce((sum, m) => sum + m[c]!, 0) / BATCHES);
  const standardError = [0, 1, 2].map((c) => Math.sqrt(batchMeans.reduce((sum, m) => sum + (m[c]! - mean[c]!) ** 2, 0) / (BATCHES - 1) / BATCHES));
  console.log(JSON.stringify({ block: [bx, by], paths: pathCount, seed: Number(seed), mean, standardError }));
}
