/** The render pool in Node (`rt render`, tests): each worker is a worker thread running render.worker.node.ts (or its prebuilt JavaScript). */
import { availableParallelism } from 'node:os';
import { RenderPool } from '../render/render-pool.ts';
import type { RenderWorkerHandlers, RenderWorkerPort } from '../render/render-worker-port.ts';
import { RENDER_WORKER_ENTRY, startRenderWorkerThread, takePrestartedRenderWorker, workerExitMessage } from './render-worker-thread.ts';

/**
 * `entry` (a file URL) is the worker module; tests pass a failing one to check recovery.
 * A thread of the same entry started ahead of any pool (prestartRenderWorker), if one waits, is used first.
 */
export function createNodeWorkerPort(handlers: RenderWorkerHandlers, entry = RENDER_WORKER_ENTRY): RenderWorkerPort {
  const prestarted = takePrestartedRenderWorker(entry);
  const worker = prestarted?.worker ?? startRenderWorkerThread(entry);
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
  worker.on('exit', (code) => fail(workerExitMessage(code)));
  // A prestarted thread that died while it waited: the pool hears it as it would have heard it live.
  const failure = prestarted?.failure;
  if (failure) queueMicrotask(() => fail(failure));
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
