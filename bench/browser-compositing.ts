import { existsSync, readFileSync } from 'node:fs';

/**
 * The two ways the browser tests composite the page, one Playwright project each
 * (playwright.config.ts), and how the benchmark table names them:
 * - 'chromium': SwiftShader is the GPU for everything, the page's compositing too. No real
 *   machine composites like this; on this project's machine that alone costs 22 ms a frame.
 * - 'software-compositing': the page is composited on the CPU and only WebGL runs on
 *   SwiftShader, as Chrome runs on a machine without a usable GPU.
 */
export const COMPOSITING = { chromium: 'page composited on SwiftShader', 'software-compositing': 'page composited on the CPU' } as const;
export type Compositing = keyof typeof COMPOSITING;
export const COMPOSITINGS = Object.keys(COMPOSITING) as Compositing[];

/**
 * Per way of compositing, what `read` makes of the last browser run's
 * test-results/<name>-<project>.json, or null when there is none or it cannot be read.
 */
export function lastBrowserRun<T>(name: string, read: (json: unknown) => T | null): Record<Compositing, T | null> {
  return Object.fromEntries(
    COMPOSITINGS.map((compositing) => {
      const file = new URL(`../test-results/${name}-${compositing}.json`, import.meta.url);
      if (!existsSync(file)) return [compositing, null];
      try {
        return [compositing, read(JSON.parse(readFileSync(file, 'utf8')))];
      } catch {
        return [compositing, null];
      }
    }),
  ) as Record<Compositing, T | null>;
}
