/** The render pool in Node (`rt render`, tests): each worker is a worker thread running render.worker.node.ts. */
import { availableParallelism } from 'node:os';
import { Worker } from 'node:worker_threads';
import { RenderPool } from '../render/render-pool.ts';
import type { RenderWorkerHandlers, RenderWorkerPort } from '../render/render-worker-port.ts';

/** Plain JavaScript that registers tsx in the new thread, then imports `workerData.entry`. */
const BOOT = new URL('../../workers/node-worker-boot.mjs', import.meta.url);
const RENDER_WORKER_ENTRY = new URL('../../workers/render.worker.node.ts', import.meta.url).href;

/** `entry` (a file URL) is the worker module; tests pass a failing one to check recovery. */
export function createNodeWorkerPort(handlers: RenderWorkerHandlers, entry = RENDER_WORKER_ENTRY): RenderWorkerPort {
  const worker = new Worker(BOOT, { workerData: { entry } });
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

