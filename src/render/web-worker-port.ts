/** The render pool in the browser: each worker is a module Web Worker running render.worker.ts. */
import { RenderPool } from './render-pool.ts';
import type { RenderWorkerHandlers, RenderWorkerPort } from './render-worker-port.ts';

/** When the browser does not say how many cores it has (some privacy modes). */
const FALLBACK_WORKERS = 4;

export function createWebWorkerPort({ onResponse, onFailure }: RenderWorkerHandlers): RenderWorkerPort {
  // Written out in full so that Vite finds and bundles the worker.
  const worker = new Worker(new URL('../../workers/render.worker.ts', import.meta.url), { type: 'module' });
  worker.onmessage = (event: MessageEvent<unknown>) => onResponse(event.data);
  worker.onerror = (event) => {
    event.preventDefault(); // reported to the UI through onFailure, not as an uncaught error
    onFailure(event.message || 'the render worker could not start');
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
