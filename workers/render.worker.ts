/** The browser's render worker (a module Web Worker): connects render-core to `self`. */
import { createRenderHandler } from './render-core.ts';
import { WORKER_STARTED, type RenderRequest } from './protocol.ts';

const handle = createRenderHandler((response, transfer) => self.postMessage(response, { transfer }));
self.onmessage = (event: MessageEvent<RenderRequest>) => handle(event.data);
// Last: this line runs only when every module above has loaded and run.
self.postMessage(WORKER_STARTED);
