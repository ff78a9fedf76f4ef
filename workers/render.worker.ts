/** The browser's render worker (a module Web Worker): connects render-core to `self`. */
import { createRenderHandler } from './render-core.ts';
import type { RenderRequest } from './protocol.ts';

const handle = createRenderHandler((response, transfer) => self.postMessage(response, { transfer }));
self.onmessage = (event: MessageEvent<RenderRequest>) => handle(event.data);
