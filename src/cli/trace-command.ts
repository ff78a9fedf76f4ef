/** `rt trace`: prints the ray tree of one pixel of the camera's screen as JSON (spec §4). */
import { DEFAULT_SEED } from '../render/render-job.ts';
import { tracePixel } from '../tracer/trace-pixel.ts';
import { buildTracerScene } from '../tracer/tracer-scene.ts';
import { InputError } from './cli-errors.ts';
import type { Command } from './command-line.ts';
import { loadSceneMeshes, readScene } from './scene-file.ts';

export const traceCommand: Command = {
  strings: ['pixel'],
  flags: ['terms'],
  help: `Usage: rt trace <scene.json|level-id> --pixel X,Y [--terms]

Prints the ray tree of one pixel of the camera's screen (camera.pixels, (0,0) top-left) as JSON:
{"pixel":[x,y],"color":[r,g,b],"rays":[one root per supersample…]}

Options:
  --pixel X,Y       the pixel's column and row (required)
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
    // One pixel: tracing here is quicker than starting a worker thread.
    const tracer = buildTracerScene(scene, await loadSceneMeshes(scene));
    process.stdout.write(`${JSON.stringify(tracePixel(tracer, x, y, DEFAULT_SEED, { terms: line.flag('terms') }))}\n`);
    return 0;
  },
};
