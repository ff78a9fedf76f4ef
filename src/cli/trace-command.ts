/** `rt trace`: prints the ray tree (path mode: the paths) of one pixel of the camera's screen as JSON (spec §4). */
import { DEFAULT_SEED } from '../render/render-job.ts';
import { LIMITS } from '../scene/scene-limits.ts';
import { tracePaths } from '../tracer/trace-paths.ts';
import { tracePixel } from '../tracer/trace-pixel.ts';
import { buildTracerScene } from '../tracer/tracer-scene.ts';
import { InputError } from './cli-errors.ts';
import type { Command } from './command-line.ts';
import { loadSceneMeshes, readScene } from './scene-file.ts';

export const traceCommand: Command = {
  strings: ['pixel', 'paths'],
  flags: ['terms'],
  help: `Usage: rt trace <scene.json|level-id> --pixel X,Y [--terms | --paths K]

Prints the ray tree of one pixel of the camera's screen (camera.pixels, (0,0) top-left) as JSON:
{"pixel":[x,y],"color":[r,g,b],"rays":[one root per supersample…]}
In path mode (settings.integrator "path") it prints the pixel's paths instead:
{"pixel":[x,y],"color":[r,g,b],"pathCount":N,"paths":[{"vertices":[…],"contribution":[r,g,b]}…]},
each vertex with its event (camera, diffuse, mirror, glass-reflect, glass-refract, emitter,
escaped, roulette-stop, max-depth, absorbed), point, normal, object or light id, sampled
direction and its pdf, the throughput after it, and its light samples; the mean of all N
contributions is the colour.

Options:
  --pixel X,Y       the pixel's column and row (required)
  --paths K         path mode: print only the first K paths (default: all)
  --terms           add to every ray that hit a surface the "terms" of its colour:
                    ambient, per light (ambient, attenuation, visibility, NdotL, RdotV,
                    diffuse, specular), reflect and refract (weight, color), and their sum
  -h, --help        show this text
`,
  async run(line) {
    const source = line.onePositional('scene file or level id');
    const pixel = line.requiredText('pixel', 'X,Y');
    const match = /^(\d+),(\d+)$/.exec(pixel.trim());
    if (!match) throw line.usageError(`--pixel must be a column and a row such as 3,2, got "${pixel}"`);
    const [x, y] = [Number(match[1]), Number(match[2])];

    const { file, scene } = await readScene(source);
    const [columns, rows] = scene.camera.pixels;
    if (x >= columns || y >= rows) {
      throw new InputError(`pixel ${x},${y} is outside the ${columns}×${rows} camera pixels of ${file} (columns 0..${columns - 1}, rows 0..${rows - 1})`);
    }
    const keep = line.wholeNumber('paths', [0, LIMITS.pathSamples[1]]);
    const pathMode = scene.settings.integrator === 'path';
    if (keep !== undefined && !pathMode) throw line.usageError('--paths is for path mode (settings.integrator "path"); this scene has ray trees');
    if (line.flag('terms') && pathMode)
      throw line.usageError('--terms is for Whitted mode; in path mode each path vertex already carries its throughput and light samples');
    // One pixel: tracing here is quicker than starting a worker thread.
    const tracer = buildTracerScene(scene, await loadSceneMeshes(scene));
    const traced = pathMode ? tracePaths(tracer, x, y, DEFAULT_SEED, keep) : tracePixel(tracer, x, y, DEFAULT_SEED, { terms: line.flag('terms') });
    process.stdout.write(`${JSON.stringify(traced)}\n`);
    return 0;
  },
};
