import { playwright } from '@vitest/browser-playwright';
import { defineConfig } from 'vitest/config';
import { levelTextsPlugin } from './scripts/level-texts-plugin.ts';

/**
 * Component tests (tests/components/): the panels and their controls rendered in a real
 * browser, driven by keyboard and pointer, checked through their properties, events and
 * declared names. Debian's Chromium, as the e2e suite uses (playwright.config.ts):
 * `npx playwright install` cannot download browsers on the school/CI machines; CI runs as
 * root, where Chromium needs --no-sandbox. SwiftShader stands in for a GPU.
 * `npm test` runs them after the unit tests: `vitest run --config vitest.browser.config.ts`.
 */
const executablePath = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

export default defineConfig({
  // The levels' texts as the app loads them (virtual:level-texts/<locale>): the export menu reads the quiz options' texts.
  plugins: [levelTextsPlugin()],
  // Found by vite only once a test imports them: bundled up front, so that a run does not
  // reload the page half-way (and load lit twice).
  optimizeDeps: {
    include: [
      'lit',
      'lit/directives/if-defined.js',
      'lit/directives/live.js',
      'lit/directives/ref.js',
      'lit/directives/repeat.js',
      'lit/directives/style-map.js',
      '@lit/context',
      '@lit/localize',
      'zod',
      'fflate',
    ],
  },
  test: {
    include: ['tests/components/**/*.test.ts'],
    // Failure screenshots go with the e2e suite's results, which git ignores.
    attachmentsDir: 'test-results/components/attachments',
    testTimeout: 30_000,
    browser: {
      enabled: true,
      headless: true,
      // Overridable so that several people can run the tests at once on one machine.
      api: { port: Number(process.env.VITEST_BROWSER_PORT ?? 63315), strictPort: false },
      viewport: { width: 1366, height: 768 },
      // A failing test leaves the page it saw.
      screenshotDirectory: 'test-results/components',
      provider: playwright({
        launchOptions: {
          executablePath,
          args: [
            '--no-sandbox',
            '--disable-background-networking',
            '--disable-component-update',
            '--no-first-run',
            '--use-angle=swiftshader',
            '--enable-unsafe-swiftshader',
          ],
        },
      }),
      instances: [{ browser: 'chromium' }],
    },
  },
});
