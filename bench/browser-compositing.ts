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
