/** `rt render`: renders a scene with the worker pool and writes a PNG, or a PFM of its linear colours (spec §4). */
import { availableParallelism } from 'node:os';
import type { FinishedRender } from '../render/render-job.ts';
import { estimateRender, lighterRenders, modelEstimate } from '../render/render-estimate.ts';
import { finalTileSide } from '../render/render-passes.ts';
import { LIMITS } from '../scene/scene-limits.ts';
import type { Scene } from '../scene/scene.ts';
import { toRgba8 } from '../tracer/quantize.ts';
import { InputError } from './cli-errors.ts';
import type { Command, CommandLine } from './command-line.ts';
import { createNodeRenderPool } from './node-worker-port.ts';
import { writePfm } from './pfm-file.ts';
import { checkWritable, writePng } from './png-file.ts';
import { loadSceneMeshes, readScene } from './scene-file.ts';
import { workersWorthStarting } from './workers-worth-starting.ts';

/**
 * Threads beyond a few per core only cost memory (each holds the scene and its BVHs):
 * `--workers 256` once took 8.26 GB for an 8×6 image.
 */
const WORKERS_PER_CORE = 4;
/** The sampler hashes the seed as a 32-bit integer. */
const SEED_RANGE: readonly [number, number] = [0, 2 ** 32 - 1];

export const renderCommand: Command = {
  strings: ['out', 'width', 'height', 'workers', 'seed', 'samples'],
  flags: ['stats', 'force'],
  help: `Usage: rt render <scene.json|level-id> --out <file.png|file.pfm> [options]

Renders a scene file, or the scene of level <level-id> (levels/<id>.level.json or
levels/*-<id>.level.json), and writes it as a PNG, or as a PFM of the linear colours
(32-bit floats, unclamped: path mode's radiance, for comparing with other renderers).

Options:
  --out <file>      where to write the image (required): .png or .pfm
  --width W         image width in pixels (default: the scene's settings.imageSize)
  --height H        image height; with only one of the two, the scene's aspect ratio is kept
  --workers N       worker threads, at most 4 per core and never more than the image has tiles
                    (default: one per core, but one for a small render, where starting
                    more threads costs more than they save)
  --seed S          seed of the random choices, 0..4294967295 (default 0)
  --samples N       path mode: N paths per pixel instead of the scene's settings.pathSamples
  --force           render even when the estimate says it takes more than a minute
  --stats           print, last, one JSON line: {"ms":…,"workers":N,"rays":{"primary":…,"shadow":…,
                    "reflect":…,"refract":…,"total":…}}; ms is the render after the threads started
  -h, --help        show this text
`,
  async run(line) {
    const source = line.onePositional('scene file or level id');
    const out = line.requiredText('out', '<file.png|file.pfm>');
    const format = /\.png$/i.test(out) ? 'png' : /\.pfm$/i.test(out) ? 'pfm' : null;
    if (format === null) throw line.usageError(`--out must name a .png or a .pfm file, the formats rt writes, got "${out}"`);
    const cores = availableParallelism();
    const requested = line.wholeNumber('workers', [1, WORKERS_PER_CORE * cores]);
    const seed = line.wholeNumber('seed', SEED_RANGE);

    const read = await readScene(source);
    const samples = line.wholeNumber('samples', LIMITS.pathSamples);
    if (samples !== undefined && read.scene.settings.integrator !== 'path')
      throw line.usageError("--samples sets path mode's paths per pixel; this scene is rendered in Whitted mode (settings.integrator)");
    const scene = samples === undefined ? read.scene : { ...read.scene, settings: { ...read.scene.settings, pathSamples: samples } };
    const [width, height] = imageSize(line, scene);
    const workers = Math.min(requested ?? workersWorthStarting(scene, width, height, cores), tileCount(scene, width, height));
    if (!line.flag('force')) refuseHeavy(scene, width, height, workers);
    await checkWritable(out);

    // The threads start before the models load: their start-up overlaps reading them.
    const pool = createNodeRenderPool(workers);
    let result: FinishedRender;
    try {
      const meshes = await loadSceneMeshes(scene);
      pool.setScene(scene, meshes);
      await pool.ready(); // so that `ms` does not count the threads' start-up
      const outcome = await pool.render(scene, meshes, { width, height, seed, preview: false }).done;
      if (outcome.cancelled) throw new InputError('the render was cancelled');
      result = outcome;
    } finally {
      pool.dispose(); // the worker threads would keep the process alive
    }

    if (format === 'pfm') await writePfm(out, result.rgb, width, height);
    else await writePng(out, toRgba8(result.rgb, width, height, scene.settings), width, height);
    process.stdout.write(`wrote ${out} (${width}×${height})\n`);
    if (line.flag('stats')) {
      const { stats } = result;
      const total = stats.primary + stats.shadow + stats.reflect + stats.refract;
      process.stdout.write(`${JSON.stringify({ ms: Math.round(result.ms), workers: result.workers, rays: { ...stats, total } })}\n`);
    }
    return 0;
  },
};

/** --width and --height, or the scene's imageSize; one of them alone keeps the scene's aspect ratio. */
function imageSize(line: CommandLine, scene: Scene): [number, number] {
  const [sceneWidth, sceneHeight] = scene.settings.imageSize;
  const width = line.wholeNumber('width', LIMITS.imageSize);
  const height = line.wholeNumber('height', LIMITS.imageSize);
  const size: [number, number] = [
    width ?? (height === undefined ? sceneWidth : Math.max(1, Math.round((height * sceneWidth) / sceneHeight))),
    height ?? (width === undefined ? sceneHeight : Math.max(1, Math.round((width * sceneHeight) / sceneWidth))),
  ];
  const [, highest] = LIMITS.imageSize;
  if (size[0] > highest || size[1] > highest) {
    throw line.usageError(`keeping the aspect ratio makes the image ${size[0]}×${size[1]}, more than ${highest} per side: give both --width and --height`);
  }
  return size;
}

/** The full-quality pass's tiles: more workers than this would have nothing to do. */
function tileCount(scene: Scene, width: number, height: number): number {
  const tileSide = finalTileSide(scene, false);
  return Math.ceil(width / tileSide) * Math.ceil(height / tileSide);
}

/** Refuses a render the estimate puts over HEAVY_RENDER_SECONDS, with lighter options to try. */
function refuseHeavy(scene: Scene, width: number, height: number, workers: number): void {
  const estimate = estimateRender(scene, width, height, workers);
  if (!estimate.heavy) return;
  const options = lighterRenders(scene, width, height, modelEstimate(workers)).map((lighter) => {
    const takes = `about ${describeSeconds(lighter.estimate.seconds)}`;
    if (lighter.change === 'supersampling') return `settings.supersampling ${lighter.supersampling} (${takes})`;
    if (lighter.change === 'max-depth') return `settings.maxDepth ${lighter.maxDepth} (${takes})`;
    if (lighter.change === 'path-samples') return `--samples ${lighter.pathSamples} (${takes})`;
    return `--width ${lighter.width} --height ${lighter.height} (${takes})`;
  });
  const lighter = options.length > 0 ? `; lighter: ${options.join(', or ')}` : '';
  throw new InputError(
    `this render would take about ${describeSeconds(estimate.seconds)} on ${workers} worker${workers === 1 ? '' : 's'} (${estimate.rays.toPrecision(2)} rays): give --force to render it anyway${lighter}`,
  );
}

/** 90 → "2 minutes", 7200 → "2 hours", 3e6 → "35 days", 3e9 → "95 years". */
export function describeSeconds(seconds: number): string {
  const units: [number, string][] = [
    [365 * 86_400, 'year'],
    [86_400, 'day'],
    [3600, 'hour'],
    [60, 'minute'],
    [1, 'second'],
  ];
  const [size, name] = units.find(([unit]) => seconds >= unit) ?? [1, 'second'];
  const count = Math.max(1, Math.round(seconds / size));
  return `${count} ${name}${count === 1 ? '' : 's'}`;
}
