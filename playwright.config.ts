import { defineConfig } from '@playwright/test';

// Debian's Chromium: `npx playwright install` cannot download browsers on the school/CI machines.
const executablePath = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';
// Overridable so that several people (or helpers) can run browser tests at once on one machine.
const port = Number(process.env.E2E_PORT ?? 4174);
const outDir = process.env.E2E_DIST ?? 'dist';
const browserArgs = [
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
  '--disable-sync',
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
];

export default defineConfig({
  testDir: 'e2e',
  timeout: 90_000,
  expect: { timeout: 20_000 },
  workers: 1,
  reporter: [['list']],
  use: {
    baseURL: `http://127.0.0.1:${port}/`,
    viewport: { width: 1366, height: 768 },
    // The app's service worker would precache the whole build in every test; e2e/offline.spec.ts allows it.
    serviceWorkers: 'block',
    // A failing test leaves the page it saw, to look at.
    screenshot: 'only-on-failure',
    launchOptions: { executablePath, args: browserArgs },
  },
  projects: [
    // Everything, with SwiftShader as the GPU: WebGL, and the page's compositing too.
    { name: 'chromium' },
    // The slider's time and a heavy render's long tasks again as Chrome runs on a machine
    // without a usable GPU: the page is composited on the CPU and only WebGL runs on
    // SwiftShader (docs/benchmarks.md, sixth and fifteenth rounds).
    {
      name: 'software-compositing',
      testMatch: ['slider-latency.spec.ts', 'render-progress.spec.ts'],
      use: { launchOptions: { executablePath, args: [...browserArgs, '--disable-gpu-compositing'] } },
    },
  ],
  webServer: {
    command: `npx vite preview --port ${port} --strictPort --outDir ${outDir}`,
    url: `http://127.0.0.1:${port}/`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
  },
});
