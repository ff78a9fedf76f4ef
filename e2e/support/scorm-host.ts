import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';

/**
 * A stand-in for a school's learning platform, for e2e/scorm.spec.ts: a web server that
 * serves unpacked SCORM packages, each under a folder of its own, and a player page whose window holds
 * scorm-again's API (an independent SCORM runtime: https://github.com/jcputney/scorm-again),
 * the way Moodle's player holds its own. The player launches the package's SCO in an
 * iframe, as platforms do.
 *
 * /player.html#<json>: `{ version: '1.2' | '2004', cmi: {…initial values…}, launch: '<folder>/…' }`.
 */

const RUNTIME = readFileSync(new URL('../../node_modules/scorm-again/dist/scorm-again.min.js', import.meta.url));

const PLAYER = `<!doctype html>
<html><head><meta charset="utf-8"><title>SCORM player</title><link rel="icon" href="data:,">
<style>html, body { margin: 0; height: 100%; } iframe { border: 0; width: 100%; height: 100%; display: block; }</style>
<script src="scorm-again.js"></script></head>
<body><script>
  const config = JSON.parse(decodeURIComponent(location.hash.slice(1)));
  const api = config.version === '2004' ? new Scorm2004API({ logLevel: 5 }) : new Scorm12API({ logLevel: 5 });
  api.loadFromJSON(config.cmi);
  window[config.version === '2004' ? 'API_1484_11' : 'API'] = api;
  window.runtime = api;
  const frame = document.createElement('iframe');
  frame.title = 'Activity';
  frame.src = config.launch;
  document.body.append(frame);
</script></body></html>`;

const TYPES: Record<string, string> = {
  html: 'text/html',
  js: 'text/javascript',
  css: 'text/css',
  svg: 'image/svg+xml',
  png: 'image/png',
  json: 'application/json',
  webmanifest: 'application/manifest+json',
  xml: 'application/xml',
};

export interface ScormHost {
  /** The paths asked for that are not there (a file missing from the package). */
  readonly missing: string[];
  /** The player's address, for `config`. */
  playerUrl(config: { version: '1.2' | '2004'; cmi: Record<string, unknown>; launch: string }): string;
  close(): Promise<void>;
}

/** `packages`: each package's files by their path in it, by the folder it is served from. */
export async function startScormHost(packages: Readonly<Record<string, Readonly<Record<string, Uint8Array>>>>): Promise<ScormHost> {
  const missing: string[] = [];
  let launches = 0;
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://host').pathname);
    const [, folder = '', ...rest] = path.split('/');
    const body = path === '/player.html' ? PLAYER : path === '/scorm-again.js' ? RUNTIME : packages[folder]?.[rest.join('/')];
    if (body === undefined) {
      missing.push(path);
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { 'content-type': TYPES[path.split('.').pop() ?? ''] ?? 'application/octet-stream' }).end(body);
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return {
    missing,
    // A query of its own per launch: a new fragment alone would not load the page again.
    playerUrl: (config) => `http://127.0.0.1:${port}/player.html?launch=${++launches}#${encodeURIComponent(JSON.stringify(config))}`,
    close: () => new Promise((resolve) => server.close(() => resolve())),
  };
}
