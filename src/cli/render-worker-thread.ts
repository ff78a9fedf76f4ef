/**
 * Starting `rt render`'s worker threads, one of them ahead of its pool (prestartRenderWorker).
 * No other import: the command's entry loads this before anything heavy.
 */
import { Worker } from 'node:worker_threads';

/**
 * This module runs either inside the prebuilt bundle of the `rt` command (build/node/, see
 * scripts/node-build.mjs), where the worker is the bundle's render-worker.mjs beside it, or
 * as TypeScript (tests, the benchmark), where the worker is the TypeScript entry.
 */
export const RENDER_WORKER_ENTRY = import.meta.url.endsWith('.ts')
  ? new URL('../../workers/render.worker.node.ts', import.meta.url).href
  : new URL('./render-worker.mjs', import.meta.url).href;
/** Plain JavaScript that registers tsx in a new thread, then imports `workerData.entry` (a .ts file). */
const BOOT = new URL('../../workers/node-worker-boot.mjs', import.meta.url);

/** A thread running `entry` (a file URL): prebuilt JavaScript directly, TypeScript through tsx. */
export function startRenderWorkerThread(entry: string): Worker {
  return entry.endsWith('.ts') ? new Worker(BOOT, { workerData: { entry } }) : new Worker(new URL(entry));
}

/** A thread started ahead of its pool, and why it failed if it did before a pool took it. */
export interface PrestartedWorker {
  worker: Worker;
  failure: string | null;
}

let waiting: { entry: string; prestarted: PrestartedWorker; stopListening: () => void } | null = null;

/**
 * Starts one render worker thread now, before `rt render` has loaded its modules and its
 * scene, so that the thread's start-up (Node's own boot, then the tracer's modules) overlaps
 * them instead of following them. The first pool to start a worker of the same entry takes
 * it (takePrestartedRenderWorker). Unreferenced until then: a command that fails on its input
 * first still exits at once. Returns the waiting thread (the one already waiting, if any).
 */
export function prestartRenderWorker(entry = RENDER_WORKER_ENTRY): PrestartedWorker {
  if (waiting?.entry === entry) return waiting.prestarted;
  // One thread waits at a time: one of another entry is not what any pool will ask for now.
  if (waiting) void takePrestartedRenderWorker(waiting.entry)?.worker.terminate();
  const prestarted: PrestartedWorker = { worker: startRenderWorkerThread(entry), failure: null };
  // Kept for the pool to hear; an 'error' nobody listens to would also end the process.
  const onError = (error: Error) => (prestarted.failure ??= error.message);
  const onExit = (code: number) => (prestarted.failure ??= workerExitMessage(code));
  prestarted.worker.on('error', onError).on('exit', onExit).unref();
  waiting = {
    entry,
    prestarted,
    stopListening: () => prestarted.worker.off('error', onError).off('exit', onExit),
  };
  return prestarted;
}

/** The prestarted thread of `entry`, referenced again so that it keeps the process alive, or null when none waits. */
export function takePrestartedRenderWorker(entry = RENDER_WORKER_ENTRY): PrestartedWorker | null {
  if (waiting?.entry !== entry) return null;
  const { prestarted, stopListening } = waiting;
  waiting = null;
  stopListening();
  // Adding the pool's 'message' listener would reference it too; said here, where it was unreferenced.
  prestarted.worker.ref();
  return prestarted;
}

/** What the pool is told when a render worker thread ends. */
export function workerExitMessage(code: number): string {
  return `the render worker exited with code ${code}`;
}
