/** The render worker for Node worker_threads (`rt render`, tests): connects render-core to parentPort. */
import { parentPort } from 'node:worker_threads';
import { createRenderHandler } from './render-core.ts';

const port = parentPort;
if (!port) throw new Error('render.worker.node.ts must run in a worker thread');
port.on(
  'message',
  createRenderHandler((response, transfer) => port.postMessage(response, transfer)),
);
