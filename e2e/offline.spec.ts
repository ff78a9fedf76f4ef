import { expect, test } from '@playwright/test';
import { existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { PNG } from 'pngjs';

// The app without a network: after one visit the service worker has every file, so a
// reload offline plays on (and the teacher's pages open); and the USB-stick build
// (`npm run build:usb`) opened from disk, file://, draws its scene and ray traces.

test.use({ serviceWorkers: 'allow' });

test('after one visit the app opens offline, with the teacher pages', async ({ page, context }) => {
  await page.goto('./');
  await expect(page.locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
  // The service worker has precached the build and controls the page.
  await expect.poll(() => page.evaluate(() => navigator.serviceWorker.controller !== null), { timeout: 30_000 }).toBe(true);
  const manifest = await page.evaluate(() => fetch(document.querySelector<HTMLLinkElement>('link[rel=manifest]')!.href).then((response) => response.json()));
  expect(manifest).toMatchObject({ name: 'Ray Tracer Quest', display: 'standalone', start_url: './' });
  // The Menu says so.
  await page.getByRole('button', { name: 'Menu' }).click();
  await expect(page.getByTestId('offline-status')).toHaveText('This app works offline: this browser keeps a copy of it.');
  await page.keyboard.press('Escape');

  await context.setOffline(true);
  await page.reload();
  await expect(page.locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
  // The dashboard is loaded on demand: from the cache too.
  await page.goto('./#/dashboard');
  await expect(page.locator('rt-dashboard-page').getByRole('heading', { name: 'Class dashboard' })).toBeVisible();
  await context.setOffline(false);
});

test('with too little storage the Menu says the app is not stored for offline use', async ({ page, baseURL }) => {
  // The browser gives the site 1 MB: the build's files (about 3 MB) do not fit, the service
  // worker never installs (issue 38), and the learner is told rather than finding out offline.
  const cdp = await page.context().newCDPSession(page);
  const origin = new URL(baseURL!).origin;
  await cdp.send('Storage.overrideQuotaForOrigin', { origin, quotaSize: 1024 * 1024 });
  try {
    await page.goto('./');
    await expect(page.locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
    await page.getByRole('button', { name: 'Menu' }).click();
    await expect(page.getByTestId('offline-status')).toHaveText(
      /^This app is not stored for offline use: the browser could not store its files, most likely for lack of storage space\./,
      { timeout: 30_000 },
    );
    expect(await page.evaluate(async () => (await navigator.serviceWorker.getRegistration())?.active ?? null)).toBeNull();
  } finally {
    // The override may outlive the page: the next tests get the usual quota.
    await cdp.send('Storage.overrideQuotaForOrigin', { origin });
  }
});

/** How many distinct colours a screenshot of `png` bytes has (a blank canvas has one or two). */
function colours(png: Buffer): number {
  const { data } = PNG.sync.read(png);
  const seen = new Set<number>();
  for (let i = 0; i < data.length; i += 4) seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
  return seen.size;
}

test('the USB-stick build opens from file:// and draws its scene', async ({ page }) => {
  const file = resolve(process.env.E2E_USB_DIST ?? 'dist-usb', 'index.html');
  expect(existsSync(file), `${file} is missing: run npm run build:usb first`).toBe(true);
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  await page.goto(`file://${file}#free-lab`);
  const canvas = page.locator('rt-scene-view canvas');
  await expect(canvas).toBeVisible();
  // The 3D view really drew: its pixels hold the scene's many colours, not a blank fill.
  await expect.poll(async () => colours(await canvas.screenshot()), { timeout: 30_000 }).toBeGreaterThan(50);

  // The render worker runs from inside the page: a full render finishes.
  await page.getByRole('button', { name: 'Render image' }).click();
  const window = page.locator('rt-render-window');
  await window.getByRole('button', { name: 'Render', exact: true }).click();
  await expect(window.getByTestId('render-status')).toContainText(/Done in [\d.]+ (ms|s)/, { timeout: 90_000 });
  expect(colours(await window.getByRole('img', { name: 'The ray traced image' }).screenshot())).toBeGreaterThan(50);
  expect(errors).toEqual([]);
});
