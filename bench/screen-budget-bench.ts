/**
 * The lab's worker tracing the free lab's screen at its largest settings with the edit
 * budget (issue 38: HEAVY_EDIT_RAYS rays of 108,836), as ScreenTracer asks for it while a
 * slider moves: this checkout's render-core against another checkout's, in alternating
 * pairs, so that a busy machine's load falls on both alike. Prints each run and the
 * medians and 95th percentiles of wall and CPU time per screen.
 *
 *   npx tsx bench/screen-budget-bench.ts <other checkout> [pairs]
 *
 * The other checkout needs its node_modules (a symlink to this one's will do).
 */
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { defaultScene } from '../src/scene/scene-defaults.ts';
import { HEAVY_EDIT_RAYS } from '../src/view/ray-budget.ts';
import type { PostResponse, RenderRequest, RenderResponse } from '../workers/protocol.ts';
import { median } from './median.ts';

type Handler = (request: RenderRequest) => void;
type CreateHandler = (post: PostResponse) => Handler;

const [otherCheckout, pairsArgument] = process.argv.slice(2);
if (!otherCheckout) throw new Error('usage: npx tsx bench/screen-budget-bench.ts <other checkout> [pairs]');
const pairs = Number(pairsArgument ?? 15);

const scene = defaultScene();
scene.camera = { ...scene.camera, aperture: 0.2, lensSamples: 4 };
scene.settings = { ...scene.settings, supersampling: 4, timeSamples: 4 };
const [columns, rows] = scene.camera.pixels;

/** A worker core of `checkout` with the scene loaded, and how to time one budgeted screen on it. */
async function workerOf(checkout: string): Promise<() => { wall: number; cpu: number; rays: number }> {
  const core = (await import(pathToFileURL(resolve(checkout, 'workers/render-core.ts')).href)) as { createRenderHandler: CreateHandler };
  let answer: RenderResponse | null = null;
  const handle = core.createRenderHandler((response) => (answer = response));
  handle({ type: 'load-scene', sceneId: 1, scene, meshes: new Map() });
  let requestId = 0;
  return () => {
    const cpu = process.cpuUsage();
    const start = performance.now();
    // The whole screen in one request (ScreenTracer asks for 64 pixels at a time; this screen has 48).
    handle({ type: 'trace-pixels', requestId: ++requestId, first: 0, count: columns * rows, seed: 1, budget: { rays: HEAVY_EDIT_RAYS, keepPixel: null } });
    const wall = performance.now() - start;
    const used = process.cpuUsage(cpu);
    const response = answer as RenderResponse | null;
    if (response?.type !== 'pixels-traced') throw new Error(`the worker answered ${JSON.stringify(response)}`);
    const rays = response.traces.reduce((sum, trace) => sum + count(trace.rays), 0);
    return { wall, cpu: (used.user + used.system) / 1000, rays };
  };
}

function count(nodes: readonly { children: readonly unknown[] }[]): number {
  let rays = 0;
  for (const node of nodes) rays += 1 + count(node.children as { children: unknown[] }[]);
  return rays;
}

const percentile95 = (values: readonly number[]) => [...values].sort((a, b) => a - b)[Math.ceil(values.length * 0.95) - 1];

const runs = { other: await workerOf(otherCheckout), this: await workerOf('.') };
// One of each first, untimed: the JIT warms up and the lazy structures are built.
runs.other();
runs.this();
const times: Record<keyof typeof runs, { wall: number[]; cpu: number[] }> = { other: { wall: [], cpu: [] }, this: { wall: [], cpu: [] } };
for (let pair = 0; pair < pairs; pair++) {
  // Alternating which goes first.
  for (const name of pair % 2 === 0 ? (['other', 'this'] as const) : (['this', 'other'] as const)) {
    const { wall, cpu, rays } = runs[name]();
    times[name].wall.push(wall);
    times[name].cpu.push(cpu);
    console.log(`${pair + 1} ${name}: ${wall.toFixed(0)} ms wall, ${cpu.toFixed(0)} ms CPU, ${rays} rays sent`);
  }
}
for (const name of ['other', 'this'] as const) {
  const { wall, cpu } = times[name];
  console.log(
    `${name} (${wall.length} runs): wall p50 ${median(wall).toFixed(0)} / p95 ${percentile95(wall).toFixed(0)} ms, CPU p50 ${median(cpu).toFixed(0)} / p95 ${percentile95(cpu).toFixed(0)} ms`,
  );
}
