import { createHash } from 'node:crypto';
import { cpSync, existsSync, readdirSync, readFileSync, renameSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { extname, join, normalize, resolve, sep } from 'node:path';

// A new build put in place under open tabs, as a school's web host does it: a server that
// serves one build folder and then, at the test's word, another, from the same address.

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.webmanifest': 'application/manifest+json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.obj': 'text/plain; charset=utf-8',
};

/**
 * Copies the build in `from` to `to` as the next build of changed code comes out: every
 * script's content and hashed name differ (here: a line added, `B` after the hash), every
 * file that names one names the new one, and the service worker's precache list has the
 * new names and the new revisions of the files kept under their own name (index.html).
 */
export function makeNewerBuild(from: string, to: string): void {
  rmSync(to, { recursive: true, force: true });
  cpSync(from, to, { recursive: true });
  const assets = join(to, 'assets');
  const scripts = readdirSync(assets).filter((name) => name.endsWith('.js'));
  const renamed = new Map(scripts.map((name) => [name, name.replace(/\.js$/, 'B.js')]));
  for (const [name, next] of renamed) {
    if (existsSync(join(assets, next))) throw new Error(`${next} is in the build already`);
    writeFileSync(join(assets, name), `${readFileSync(join(assets, name), 'utf8')}\n// the newer build\n`);
    renameSync(join(assets, name), join(assets, next));
  }
  const textFiles = [...[...renamed.values()].map((name) => join(assets, name)), join(to, 'index.html'), join(to, 'sw.js')];
  for (const file of textFiles) {
    let text = readFileSync(file, 'utf8');
    for (const [name, next] of renamed) text = text.replaceAll(name, next);
    writeFileSync(file, text);
  }
  // Workbox's revision of a file without a hash in its name is the MD5 of its content.
  const worker = join(to, 'sw.js');
  const revised = readFileSync(worker, 'utf8').replace(/\{url:"([^"]+)",revision:"[0-9a-f]{32}"\}/g, (_, url: string) => {
    const revision = createHash('md5')
      .update(readFileSync(join(to, url)))
      .digest('hex');
    return `{url:"${url}",revision:"${revision}"}`;
  });
  writeFileSync(worker, revised);
}

/** What the server answered a request for `path` with. */
export interface Served {
  path: string;
  status: number;
}

export interface SwitchingServer {
  /** The server's address, ending in '/'. */
  url: string;
  /** Every request since the server started, in order. */
  requests: Served[];
  /** Serves the build in `folder` from now on. */
  serve(folder: string): void;
  close(): Promise<void>;
}

/** A static server on a free port of 127.0.0.1 (a secure context: service workers run), serving `folder`. */
export async function startSwitchingServer(folder: string): Promise<SwitchingServer> {
  let root = resolve(folder);
  const requests: Served[] = [];
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://server').pathname);
    const file = normalize(join(root, path === '/' ? 'index.html' : path));
    const found = file.startsWith(root + sep) && existsSync(file) && statSync(file).isFile();
    requests.push({ path, status: found ? 200 : 404 });
    if (!found) {
      response.writeHead(404, { 'Content-Type': 'text/plain' }).end('Not found');
      return;
    }
    // As a host that checks with the server on every use: the browser's HTTP cache never hides a new build.
    response.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream', 'Cache-Control': 'no-cache' });
    response.end(readFileSync(file));
  });
  await new Promise<void>((done) => server.listen(0, '127.0.0.1', done));
  const { port } = server.address() as AddressInfo;
  return {
    url: `http://127.0.0.1:${port}/`,
    requests,
    serve: (next) => (root = resolve(next)),
    close: () =>
      new Promise((done) => {
        server.close(() => done());
        server.closeAllConnections();
      }),
  };
}
