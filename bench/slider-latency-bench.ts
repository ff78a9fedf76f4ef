/**
 * Slider to rays (issue: tracer speed, "interactive edits": ≤ 100 ms at the 95th
 * percentile on a 16×16 screen, without skipping the last value). A Node proxy of the lab,
 * wired as LabServices wires it (the store, the screen tracer with its inline tracer and one
 * worker thread, the ray pool; LabServices itself loads models through the browser), so it
 * measures everything from the store's dispatch to the ray pool's new instance buffers and
 * leaves out the browser's parts: the panels' update and the GPU's frame.
 *
 * A step's latency runs from its dispatch to the first rays drawn from a scene at least as
 * new as it (a later step's rays also show it). Two ways of moving a slider: a drag (a step
 * every 16 ms, one per frame) and arrow-key presses (a step every 150 ms). The first drag
 * after the lab opens is measured apart: its screens trace while V8 is still compiling the
 * tracer (in the worker) and the ray pool (here), so it shows what the learner's first drag
 * costs; the later drag and the key presses show the steady state.
 */
import { createNodeRenderPool } from '../src/cli/node-worker-port.ts';
import { initialState } from '../src/lab-state/lab-state.ts';
import { Store } from '../src/lab-state/store.ts';
import { InlineScreenTracer } from '../src/render/inline-screen-tracer.ts';
import { ScreenTracer } from '../src/render/screen-tracer.ts';
import { defaultScene } from '../src/scene/scene-defaults.ts';
import type { Scene } from '../src/scene/scene.ts';
import { loadMeshesFromDisk } from '../src/scene/load-meshes-node.ts';
import { RayPool } from '../src/view/ray-pool.ts';

/** The lab's chain from a scene edit to drawn rays, as LabServices wires it. */
interface Lab {
  store: Store;
  /** Calls `listener` after the ray pool has taken each new screen; returns the unsubscribe. */
  subscribe(listener: () => void): () => void;
}

export interface SliderLatency {
  steps: number;
  p50Ms: number;
  p95Ms: number;
  maxMs: number;
  /** Whether the last value's rays were drawn. */
  lastDrawn: boolean;
}

export interface SliderBenchResults {
  /** The first drag, just after the first screens: the JIT has not compiled the hot code yet. */
  firstDrag: SliderLatency;
  drag: SliderLatency;
  keys: SliderLatency;
}

const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

function percentile(values: number[], p: number): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.ceil(p * sorted.length) - 1)];
}

/** `steps` moves of the first object's x, `everyMs` apart; the rays' scene is the one the last published screen was traced in. */
async function moveSlider(services: Lab, sceneOfRays: () => Scene | null, steps: number, everyMs: number): Promise<SliderLatency> {
  const dispatched: { scene: Scene; at: number }[] = [];
  // What each published screen showed, and when: a cheap screen is published inside the dispatch, before it returns.
  const shown: { scene: Scene | null; at: number }[] = [];
  const stop = services.subscribe(() => shown.push({ scene: sceneOfRays(), at: performance.now() }));
  const drawnAt = (step: number): number | undefined => shown.find(({ scene }) => dispatched.findIndex((sent) => sent.scene === scene) >= step)?.at;
  const object = services.store.state.scene.objects[0];
  for (let i = 0; i < steps; i++) {
    const at = performance.now();
    services.store.dispatch({
      type: 'object.changed',
      id: object.id,
      changes: { position: [object.position[0] + 0.01 * (i + 1), object.position[1], object.position[2]] },
    });
    dispatched.push({ scene: services.store.state.scene, at });
    await sleep(everyMs);
  }
  const deadline = performance.now() + 10_000;
  while (drawnAt(steps - 1) === undefined && performance.now() < deadline) await sleep(5);
  stop();
  const latencies = dispatched.map(({ at }, i) => (drawnAt(i) ?? Infinity) - at);
  const round = (ms: number) => Number(ms.toFixed(1));
  return {
    steps,
    p50Ms: round(percentile(latencies, 0.5)),
    p95Ms: round(percentile(latencies, 0.95)),
    maxMs: round(Math.max(...latencies)),
    lastDrawn: drawnAt(steps - 1) !== undefined,
  };
}

export async function measureSliderLatency(): Promise<SliderBenchResults> {
  const pool = createNodeRenderPool(1);
  let sceneOfRays: Scene | null = null;
  const store = new Store(initialState(defaultScene()));
  const tracer = new ScreenTracer(pool, loadMeshesFromDisk);
  const rayPool = new RayPool();
  const listeners = new Set<() => void>();
  tracer.subscribe((rays) => {
    sceneOfRays = rays.scene ?? null;
    rayPool.update(rays, store.state.rays, store.state.selectedPixel);
    for (const listener of listeners) listener();
  });
  const stopStore = store.subscribe((state) => tracer.update(state.scene));
  // As the lab does once its 3D view has loaded: cheap screens are traced inside the dispatch.
  tracer.traceInline(new InlineScreenTracer());
  const lab: Lab = { store, subscribe: (listener) => (listeners.add(listener), () => listeners.delete(listener)) };
  try {
    store.dispatch({ type: 'camera.changed', changes: { pixels: [16, 16] } });
    // Warm-up: the worker starts, compiles the tracer and builds the models' BVHs.
    await moveSlider(lab, () => sceneOfRays, 3, 400);
    const firstDrag = await moveSlider(lab, () => sceneOfRays, 60, 16);
    await sleep(500);
    const drag = await moveSlider(lab, () => sceneOfRays, 60, 16);
    await sleep(500);
    const keys = await moveSlider(lab, () => sceneOfRays, 30, 150);
    return { firstDrag, drag, keys };
  } finally {
    stopStore();
    tracer.dispose();
    rayPool.dispose();
    pool.dispose();
  }
}

export function sliderRows({ firstDrag, drag, keys }: SliderBenchResults): [string, string, string][] {
  const row = (name: string, latency: SliderLatency): [string, string, string] => [
    `slider to rays, 16×16 screen, ${name} (${latency.steps} steps)`,
    `p50 ${latency.p50Ms} / p95 ${latency.p95Ms} / max ${latency.maxMs} ms${latency.lastDrawn ? '' : ', last value NOT drawn'}`,
    '≤ 100 ms p95',
  ];
  return [
    row('first drag (JIT still compiling), a step per 16 ms', firstDrag),
    row('drag, a step per 16 ms', drag),
    row('arrow keys, a step per 150 ms', keys),
  ];
}

if (process.argv[1]?.endsWith('slider-latency-bench.ts')) {
  const { printTable } = await import('./print-table.ts');
  printTable(sliderRows(await measureSliderLatency()));
}
