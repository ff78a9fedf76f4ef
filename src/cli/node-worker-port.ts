/** The render pool in Node (`rt render`, tests): each worker is a worker thread running render.worker.node.ts (or its prebuilt JavaScript). */
import { availableParallelism } from 'node:os';
import { Worker } from 'node:worker_threads';
import { RenderPool } from '../render/render-pool.ts';
import type { RenderWorkerHandlers, RenderWorkerPort } from '../render/render-worker-port.ts';

/**
 * This module runs either inside the prebuilt bundle of the `rt` command (build/node/, see
 * scripts/node-build.mjs), where the worker is the bundle's render-worker.mjs beside it, or
 * as TypeScript (tests, the benchmark), where the worker is the TypeScript entry.
 */
const RENDER_WORKER_ENTRY = import.meta.url.endsWith('.ts')
  ? new URL('../../workers/render.worker.node.ts', import.meta.url).href
  : new URL('./render-worker.mjs', import.meta.url).href;
/** Plain JavaScript that registers tsx in a new thread, then imports `workerData.entry` (a .ts file). */
const BOOT = new URL('../../workers/node-worker-boot.mjs', import.meta.url);

/** `entry` (a file URL) is the worker module; tests pass a failing one to check recovery. */
export function createNodeWorkerPort(handlers: RenderWorkerHandlers, entry = RENDER_WORKER_ENTRY): RenderWorkerPort {
  const worker = entry.endsWith('.ts') ? new Worker(BOOT, { workerData: { entry } }) : new Worker(new URL(entry));
  let stopped = false;
  const fail = (message: string) => {
    if (stopped) return;
    stopped = true;
    handlers.onFailure(message);
  };
  worker.on('message', (data: unknown) => {
    if (!stopped) handlers.onResponse(data);
  });
  worker.on('error', (error) => fail(error.message));
  worker.on('messageerror', () => fail('a message from the render worker could not be read'));
  worker.on('exit', (code) => fail(`the render worker exited with code ${code}`));
  return {
    post: (request) => worker.postMessage(request),
    terminate: () => {
      stopped = true;
      void worker.terminate();
    },
  };
}

export function createNodeRenderPool(size = availableParallelism()): RenderPool {
  return new RenderPool({ size, createWorker: createNodeWorkerPort });
}

