/**
 * The URL of every figure a task can show (assets/figures, a level's `figure.src`). Vite
 * bundles the folder: the web build copies each file in with a hashed name or, under 4 kB,
 * writes it into the script as a data: URL; the USB build (vite.usb.config.ts) inlines them
 * all. Either is allowed by the build's Content-Security-Policy (img-src 'self' data:).
 */
const FIGURE_URLS: ReadonlyMap<string, string> = new Map(
  Object.entries(import.meta.glob<string>('../../../assets/figures/*.{svg,png}', { query: '?url', import: 'default', eager: true })).map(([path, url]) => [
    path.slice(path.lastIndexOf('/') + 1),
    url,
  ]),
);

/** The figure's URL; undefined only for a name the level schema would have refused (src/quest/figure-files.ts lists the folder). */
export function figureUrl(file: string): string | undefined {
  return FIGURE_URLS.get(file);
}
