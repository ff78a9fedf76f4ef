/**
 * What the render pool needs from one worker, whatever runs it: a browser Web Worker
 * (web-worker-port.ts) or a Node worker thread (src/cli/node-worker-port.ts).
 */
import type { RenderRequest } from '../../workers/protocol.ts';

export interface RenderWorkerPort {
  post(request: RenderRequest): void;
  /** Stops the worker at once; no handler is called after this. */
  terminate(): void;
}

export interface RenderWorkerHandlers {
  /** Whatever the worker posted: the pool checks that it is a RenderResponse (render-response-check.ts). */
  onResponse(data: unknown): void;
  /**
   * The worker died or could not start; `message` says why, for the user. Called at most once.
   * `not-started`: its code could not be loaded or run (a new build removed the file, no
   * connection), which a new worker cannot mend; the browser's port tells it, Node's does not.
   */
  onFailure(message: string, kind?: 'not-started'): void;
}

/** Starts one worker that reports to `handlers`. */
export type CreateRenderWorker = (handlers: RenderWorkerHandlers) => RenderWorkerPort;
