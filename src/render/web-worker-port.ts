/** The render pool in the browser: each worker is a module Web Worker running render.worker.ts. */
import { RenderPool } from './render-pool.ts';
import type { RenderWorkerHandlers, RenderWorkerPort } from './render-worker-port.ts';
import { WORKER_STARTED } from '../../workers/protocol.ts';

/** When the browser does not say how many cores it has (some privacy modes). */
const FALLBACK_WORKERS = 4;

export function createWebWorkerPort({ onResponse, onFailure }: RenderWorkerHandlers): RenderWorkerPort {
  // Written out in full so that Vite finds and bundles the worker.
  const worker = new Worker(new URL('../../workers/render.worker.ts', import.meta.url), { type: 'module' });
  // The worker says when its code has loaded and run (render.worker.ts); an error before that
  // is code that could not be loaded: its file is gone (a newer build) or out of reach (offline).
  let started = false;
  worker.onmessage = (event: MessageEvent<unknown>) => {
    if (event.data === WORKER_STARTED) started = true;
    else onResponse(event.data);
  };
  worker.onerror = (event) => {
    event.preventDefault(); // reported to the UI through onFailure, not as an uncaught error
    if (started) onFailure(event.message || 'the render worker stopped');
    else onFailure(event.message || "the render worker's code could not be loaded", 'not-started');
  };
  worker.onmessageerror = () => onFailure('a message from the render worker could not be read');
  return {
    post: (request) => worker.postMessage(request),
    terminate: () => worker.terminate(),
  };
}

export function createBrowserRenderPool(size = navigator.hardwareConcurrency || FALLBACK_WORKERS): RenderPool {
  return new RenderPool({ size, createWorker: createWebWorkerPort });
}
