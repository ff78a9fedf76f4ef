/**
 * An edit that arrives while the lab traces the settled screen (issue 38): the free lab's
 * largest settings (108,836 rays a screen), traced by ScreenTracer in a worker thread as the
 * lab asks for it on a CPU rasterizer: a budgeted screen, the budget ends (the full screen
 * starts), and `delay` ms later the next edit brings the budget back with a new scene. Timed:
 * from that edit to its own screen published. This checkout's ScreenTracer against another
 * module of it (e.g. the file as it was, `git show <commit>:src/render/screen-tracer.ts` saved
 * beside it), in alternating pairs, each with its own worker, so that a busy machine's load
 * falls on both alike.
 *
 *   npx tsx bench/settled-edit-bench.ts <other screen-tracer.ts> [pairs]
 */
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { createNodeRenderPool } from '../src/cli/node-worker-port.ts';
import type { RenderPool } from '../src/render/render-pool.ts';
import type { ScreenRays } from '../src/render/screen-rays.ts';
import { ScreenTracer } from '../src/render/screen-tracer.ts';
import type { MeshLibrary } from '../src/scene/mesh-data.ts';
import { defaultScene } from '../src/scene/scene-defaults.ts';
import type { Scene } from '../src/scene/scene.ts';
import { HEAVY_EDIT_RAYS } from '../src/view/ray-budget.ts';
import { median } from './median.ts';

const [otherModule, pairsArgument] = process.argv.slice(2);
if (!otherModule) throw new Error('usage: npx tsx bench/settled-edit-bench.ts <other screen-tracer.ts> [pairs]');
const pairs = Number(pairsArgument ?? 8);
/** When the edit comes after the budget ended, ms: early, mid-trace and late in the settled screen. */
const DELAYS = [50, 150, 300, 500];

function freeLabLargest(shininess: number): Scene {
  const scene = defaultScene();
  return {
    ...scene,
    camera: { ...scene.camera, aperture: 0.2, lensSamples: 4 },
    settings: { ...scene.settings, supersampling: 4, timeSamples: 4 },
    objects: scene.objects.map((object) => (object.id === 'red-ball' ? { ...object, material: { ...object.material, shininess } } : object)),
  };
}

type Tracer = Pick<ScreenTracer, 'setBudget' | 'update' | 'subscribe' | 'dispose' | 'onError'>;
type TracerClass = new (pool: RenderPool, loadMeshes: (names: string[]) => Promise<MeshLibrary>) => Tracer;

function published(tracer: Tracer, scene: Scene): Promise<ScreenRays> {
  return new Promise((done) => {
    const stop = tracer.subscribe((rays) => {
      if (rays.scene !== scene) return;
      queueMicrotask(() => stop());
      done(rays);
    });
  });
}

const pause = (ms: number) => new Promise((done) => setTimeout(done, ms));
const budget = { rays: HEAVY_EDIT_RAYS, keepPixel: null };
let shininess = 10;

/** A run whose edit's screen had not come after this long counts as this long; its errors are said. */
const GIVE_UP_MS = 30_000;

/** One edit `delay` ms into the settled screen: ms from the edit to its screen, and the errors meanwhile. */
async function editDuringSettled(Tracer: TracerClass, pool: RenderPool, delay: number): Promise<{ ms: number; errors: string[] }> {
  const tracer = new Tracer(pool, () => Promise.resolve(new Map()));
  const errors: string[] = [];
  tracer.onError = (error) => errors.push(error.message);
  try {
    const before = freeLabLargest(shininess++);
    tracer.setBudget(budget);
    const thinned = published(tracer, before);
    tracer.update(before);
    await thinned;
    tracer.setBudget(null);
    await pause(delay);
    const edited = freeLabLargest(shininess++);
    const start = performance.now();
    const shown = published(tracer, edited);
    tracer.setBudget(budget);
    tracer.update(edited);
    await Promise.race([shown, pause(GIVE_UP_MS)]);
    return { ms: Math.min(GIVE_UP_MS, performance.now() - start), errors };
  } finally {
    tracer.dispose();
    // Whatever the worker still does for the disposed tracer ends before the next run.
    await pause(1500);
  }
}

const other = ((await import(pathToFileURL(resolve(otherModule)).href)) as { ScreenTracer: TracerClass }).ScreenTracer;
const variants: [string, TracerClass, RenderPool][] = [
  ['this checkout', ScreenTracer, createNodeRenderPool(1)],
  [otherModule, other, createNodeRenderPool(1)],
];
const times = new Map<string, number[]>(variants.map(([name]) => [name, []]));
for (let pair = 0; pair < pairs; pair++) {
  const delay = DELAYS[pair % DELAYS.length];
  const order = pair % 2 === 0 ? variants : [...variants].reverse();
  const line: string[] = [];
  for (const [name, Tracer, pool] of order) {
    const { ms, errors } = await editDuringSettled(Tracer, pool, delay);
    times.get(name)!.push(ms);
    line.push(`${name}: ${ms >= GIVE_UP_MS ? 'not shown in 30 s' : `${ms.toFixed(0)} ms`}${errors.length > 0 ? ` (${errors.join('; ')})` : ''}`);
  }
  console.log(`pair ${pair + 1}, edit ${delay} ms into the settled screen: ${line.join(', ')}`);
}
const percentile95 = (values: readonly number[]) => [...values].sort((a, b) => a - b)[Math.ceil(values.length * 0.95) - 1];
for (const [name, ms] of times)
  console.log(
    `${name} (${ms.length} runs): edit to its screen p50 ${median(ms).toFixed(0)} / p95 ${percentile95(ms).toFixed(0)} / max ${Math.max(...ms).toFixed(0)} ms`,
  );
for (const [, , pool] of variants) pool.dispose();
