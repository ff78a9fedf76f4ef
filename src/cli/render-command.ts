/** `rt render`: renders a scene with the worker pool and writes a PNG (spec §4). */
import { availableParallelism } from 'node:os';
import type { FinishedRender } from '../render/render-job.ts';
import { LIMITS } from '../scene/scene-limits.ts';
import type { Scene } from '../scene/scene.ts';
import { toRgba8 } from '../tracer/quantize.ts';
import { InputError } from './cli-errors.ts';
import type { Command, CommandLine } from './command-line.ts';
import { createNodeRenderPool } from './node-worker-port.ts';
import { checkWritable, writePng } from './png-file.ts';
import { loadSceneMeshes, readScene } from './scene-file.ts';

/** More threads than this only cost memory (each holds the scene); 256 is far past any core count. */
const WORKER_RANGE: readonly [number, number] = [1, 256];
/** The sampler hashes the seed as a 32-bit integer. */
const SEED_RANGE: readonly [number, number] = [0, 2 ** 32 - 1];

export const renderCommand: Command = {
  strings: ['out', 'width', 'height', 'workers', 'seed'],
  flags: ['stats'],
  help: `Usage: rt render <scene.json|level-id> --out <file.png> [options]

Renders a scene file, or the scene of level <level-id> (levels/<id>.level.json or
levels/*-<id>.level.json), and writes it as a PNG.

Options:
  --out <file.png>  where to write the image (required)
  --width W         image width in pixels (default: the scene's settings.imageSize)
  --height H        image height; with only one of the two, the scene's aspect ratio is kept
  --workers N       worker threads (default: the number of cores)
  --seed S          seed of the random choices, 0..4294967295 (default 0)
  --stats           print, last, one JSON line: {"ms":…,"workers":N,"rays":{"primary":…,"shadow":…,
                    "reflect":…,"refract":…,"total":…}}; ms is the render after the threads started
  -h, --help        show this text
`,
  async run(line) {
    const source = line.onePositional('scene file or level id');
    const out = line.requiredText('out', '<file.png>');
    const workers = line.wholeNumber('workers', WORKER_RANGE) ?? availableParallelism();
    const seed = line.wholeNumber('seed', SEED_RANGE);

    // The threads start first: their start-up overlaps reading the scene and its models.
    const pool = createNodeRenderPool(workers);
    let scene: Scene;
    let width: number;
    let height: number;
    let result: FinishedRender;
    try {
      ({ scene } = await readScene(source));
      [width, height] = imageSize(line, scene);
      await checkWritable(out);
      const meshes = await loadSceneMeshes(scene);
      pool.setScene(scene, meshes);
      await pool.ready(); // so that `ms` does not count the threads' start-up
      const outcome = await pool.render(scene, meshes, { width, height, seed, preview: false }).done;
      if (outcome.cancelled) throw new InputError('the render was cancelled');
      result = outcome;
    } finally {
      pool.dispose(); // the worker threads would keep the process alive
    }

    await writePng(out, toRgba8(result.rgb, width, height, scene.settings.dithering), width, height);
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
