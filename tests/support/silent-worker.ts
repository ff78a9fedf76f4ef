/**
 * A render worker that answers its first few tiles and then falls silent without an error,
 * as a browser worker does after `self.close()`: for testing the pool's deadlines.
 */
import { parentPort } from 'node:worker_threads';
import { createRenderHandler } from '../../workers/render-core.ts';

const ANSWERED_TILES = 3;
let tiles = 0;
const port = parentPort;
if (!port) throw new Error('silent-worker.ts must run in a worker thread');
const handle = createRenderHandler((response, transfer) => {
  if (response.type === 'tile-done' && ++tiles > ANSWERED_TILES) return;
  if (tiles > ANSWERED_TILES) return;
  port.postMessage(response, transfer);
});
port.on('message', handle);
