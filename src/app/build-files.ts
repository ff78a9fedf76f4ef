/**
 * The files of the running build, fetched from its own server: what a SCORM package holds
 * (the teacher page's download, classroom/scorm/scorm-package.ts).
 *
 * The list is the service worker's precache list: Workbox writes every file of the build
 * (`globPatterns` in vite.config.ts: scripts, styles, models, icons, index.html) into
 * `sw.js` as `{url:"…",revision:…}`, and the offline copy already depends on it being
 * complete (docs/offline.md). The worker and its Workbox script are not in the list, and
 * not needed in a package. The dev server has no `sw.js` (vite-plugin-pwa builds it only in
 * a build), nor does the USB-stick build: there the list is null and the page says so.
 */

const WORKER_FILE = 'sw.js';
const PRECACHED = /\burl:\s*"([^"]+)"/g;

/** The build's file paths, or null when this page was not served from a build with a service worker. */
export async function listBuildFiles(base: string): Promise<string[] | null> {
  let text: string;
  try {
    const response = await fetch(new URL(WORKER_FILE, base));
    if (!response.ok) return null;
    text = await response.text();
  } catch {
    return null;
  }
  const files = [...new Set([...text.matchAll(PRECACHED)].map((match) => match[1]))].filter((path) => !/^[a-z]+:|^\/|\.\./i.test(path));
  return files.includes('index.html') ? files : null;
}

/** Each file's bytes; throws with the file's name when one cannot be fetched. */
export async function fetchBuildFiles(base: string, paths: readonly string[], progress?: (done: number) => void): Promise<Map<string, Uint8Array>> {
  const files = new Map<string, Uint8Array>();
  for (const path of paths) {
    const response = await fetch(new URL(path, base));
    if (!response.ok) throw new Error(`${path}: ${response.status} ${response.statusText}`);
    files.set(path, new Uint8Array(await response.arrayBuffer()));
    progress?.(files.size);
  }
  return files;
}
