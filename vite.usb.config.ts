import { readFileSync } from 'node:fs';
import { defineConfig, type Plugin } from 'vite';
import { viteSingleFile } from 'vite-plugin-singlefile';
import { levelTextsPlugin } from './scripts/level-texts-plugin.ts';

/**
 * The USB-stick build (`npm run build:usb`): one `index.html` that opens by double-click.
 *
 * A page opened from disk (file://) may not load module scripts, workers or anything else
 * from files next to it (browsers treat every file as its own origin). So everything goes
 * inside the page: the script inline (vite-plugin-singlefile), the models and icons as data
 * URLs, and the render worker as an inline worker (Vite's `?worker&inline`, started from a
 * blob), the code lab's sandbox page as the frame's `srcdoc`. No service worker: file://
 * pages cannot register one, and nothing needs caching.
 */

const WORKER_PORT = /src\/render\/web-worker-port\.ts$/;
const WORKER_URL = "new Worker(new URL('../../workers/render.worker.ts', import.meta.url), { type: 'module' })";

/** Starts the render worker from the page's own text instead of a file beside it. */
function inlineRenderWorker(): Plugin {
  return {
    name: 'inline-render-worker',
    enforce: 'pre',
    transform(code, id) {
      if (!WORKER_PORT.test(id)) return null;
      if (!code.includes(WORKER_URL)) this.error(`${id} no longer starts the render worker as ${WORKER_URL}: update vite.usb.config.ts`);
      return `import InlineRenderWorker from '../../workers/render.worker.ts?worker&inline';\n${code.replace(WORKER_URL, 'new InlineRenderWorker()')}`;
    },
  };
}

const SANDBOX_PORT = /src\/ui\/game\/code-lab\/lab-sandbox\.ts$/;
const SANDBOX_SRC = "frame.src = 'code-lab-sandbox-host.html';";

/**
 * Frames the code lab's sandbox page itself, as text, instead of the host page beside
 * index.html, which a stick may not hold. The host page is there for the service worker and
 * the app's policy (docs/code-labs.md), and this build has neither. The frame is sandboxed
 * without allow-same-origin (an opaque origin), as the host frames it, and the page's own
 * policy (its <meta>) holds in it: this build's page has none to pass on.
 */
function inlineCodeLabSandbox(): Plugin {
  return {
    name: 'inline-code-lab-sandbox',
    enforce: 'pre',
    transform(code, id) {
      if (!SANDBOX_PORT.test(id)) return null;
      if (!code.includes(SANDBOX_SRC)) this.error(`${id} no longer loads the sandbox's host as ${SANDBOX_SRC}: update vite.usb.config.ts`);
      const page = readFileSync(new URL('public/code-lab-sandbox.html', import.meta.url), 'utf8');
      return code.replace(SANDBOX_SRC, `frame.sandbox.add('allow-scripts');\nframe.srcdoc = ${JSON.stringify(page)};`);
    },
  };
}

export default defineConfig({
  base: './',
  // A classic worker: a module worker from a blob is refused on a file:// page.
  worker: { format: 'iife' },
  build: {
    target: 'es2022',
    outDir: 'dist-usb',
    assetsInlineLimit: () => true,
    chunkSizeWarningLimit: 8000,
  },
  plugins: [levelTextsPlugin(), inlineRenderWorker(), inlineCodeLabSandbox(), viteSingleFile()],
});
