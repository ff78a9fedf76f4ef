import { expect, test, type Locator, type Page } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import type { LabAction } from '../src/lab-state/lab-action.ts';
import type { Store } from '../src/lab-state/store.ts';

/**
 * The rays as a student meets them: the camera's pixels are traced and drawn, hovering a
 * ray names it, hiding rays that hit nothing and choosing a pixel thin them out, and the
 * page stays responsive while scene edits keep the tracer busy.
 *
 * What it relies on in the lab: <rt-ray-panel>, <rt-screen-preview> and <rt-ray-tooltip>
 * (each with the store), and the 3D view's element carrying `data-ray-instances` (the ray
 * pool's drawn cylinders, updated after each rebuild) around its canvas.
 */

/** The page under test: the app. */
const PAGE = './#free-lab';

declare global {
  interface Window {
    /** Durations of the main thread's long tasks (> 50 ms), collected from page start. */
    rtLongTasks: number[];
  }
}

/** How many rays the view draws now. */
async function drawnRays(page: Page): Promise<number> {
  return Number(await page.locator('[data-ray-instances]').first().getAttribute('data-ray-instances'));
}

/** Dispatches an action on the lab's store (the one every lab element holds). */
async function dispatch(page: Page, action: LabAction): Promise<void> {
  await page.locator('rt-ray-panel').evaluate((panel, a) => (panel as HTMLElement & { store: Store }).store.dispatch(a), action);
}

/** Distinct colours in a screenshot of `locator`: a blank or single-colour canvas has a handful. */
async function distinctColours(locator: Locator): Promise<number> {
  const png = PNG.sync.read(await locator.screenshot());
  const colours = new Set<number>();
  for (let i = 0; i < png.data.length; i += 4) colours.add((png.data[i] << 16) | (png.data[i + 1] << 8) | png.data[i + 2]);
  return colours.size;
}

/** Moves the pointer over the view in a grid until the ray tooltip shows; returns where, or null. */
async function findRayUnderPointer(page: Page, view: Locator): Promise<{ x: number; y: number } | null> {
  const box = await view.boundingBox();
  if (!box) return null;
  const tooltip = page.locator('rt-ray-tooltip');
  for (let y = box.y + 20; y < box.y + box.height - 20; y += 16) {
    for (let x = box.x + 20; x < box.x + box.width - 20; x += 16) {
      await page.mouse.move(x, y);
      // The view picks once per animation frame.
      await page.evaluate(() => new Promise(requestAnimationFrame));
      if (await tooltip.isVisible()) return { x, y };
    }
  }
  return null;
}

test("the camera pixels' rays: drawn, hovered, filtered by hit and by pixel, and the page stays responsive", async ({ page }) => {
  test.setTimeout(180_000);
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.addInitScript(() => {
    window.rtLongTasks = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) window.rtLongTasks.push(entry.duration);
    }).observe({ type: 'longtask', buffered: true });
  });

  const loadStarted = Date.now();
  await page.goto(PAGE);
  const rays = page.locator('[data-ray-instances]').first();
  await expect(rays).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 60_000 });
  const firstRaysMs = Date.now() - loadStarted;
  const all = await drawnRays(page);

  // The canvas really drew (rays, floor, objects in many shades), not a blank frame.
  const canvas = rays.locator('canvas').first();
  expect(await distinctColours(canvas)).toBeGreaterThan(200);

  // Hovering a ray names it, with its contribution as a percentage.
  const spot = await findRayUnderPointer(page, canvas);
  expect(spot, 'some ray should be under the pointer somewhere in the view').not.toBeNull();
  const tooltip = page.locator('rt-ray-tooltip');
  await expect(tooltip).toContainText(/ray|cone/i);
  await expect(tooltip.getByTestId('ray-contribution')).toHaveText(/%/);
  await page.screenshot({ path: 'test-results/screens/rays-hover.png' });
  await page.mouse.move(1, 1);

  // Hiding the rays that hit nothing draws fewer (the default scene has sky in view).
  const hideNoHit = page.locator('rt-switch[name="hideNoHit"] input');
  await hideNoHit.check();
  await expect.poll(() => drawnRays(page)).toBeLessThan(all);
  await hideNoHit.uncheck();
  await expect.poll(() => drawnRays(page)).toBe(all);

  // Choosing a pixel shows only its rays; choosing it again shows them all.
  const cell = page.getByRole('button', { name: 'Pixel 4, 3', exact: true });
  await cell.click();
  await expect(cell).toHaveAttribute('aria-pressed', 'true');
  await expect.poll(() => drawnRays(page)).toBeLessThan(all);
  expect(await drawnRays(page)).toBeGreaterThan(0);
  await page.screenshot({ path: 'test-results/screens/rays-one-pixel.png' });
  await cell.click();
  await expect.poll(() => drawnRays(page)).toBe(all);

  // Responsiveness while tracing: a 16×16 screen with 2×2 supersampling (thousands of rays),
  // then 30 field-of-view edits (each pause
  // past the debounce starts a trace), each followed by a transparency slider step (a pool
  // rebuild) while traces run.
  await dispatch(page, { type: 'camera.changed', changes: { pixels: [16, 16] } });
  await dispatch(page, { type: 'settings.changed', changes: { supersampling: 2 } });
  await expect.poll(() => drawnRays(page), { timeout: 60_000 }).toBeGreaterThan(all);
  const transparency = page.locator('rt-slider[name="transparency"] input[type="range"]');
  await page.evaluate(() => (window.rtLongTasks = []));
  const editsStarted = Date.now();
  for (let i = 0; i < 30; i++) {
    await dispatch(page, { type: 'camera.changed', changes: { fov: 40 + (i % 10) } });
    await transparency.press(i % 12 < 6 ? 'ArrowRight' : 'ArrowLeft');
    await page.waitForTimeout(i % 3 === 0 ? 120 : 30);
  }
  const rays16 = await drawnRays(page);
  const editsMs = Date.now() - editsStarted;
  const longTasks = await page.evaluate(() => window.rtLongTasks);
  await page.screenshot({ path: 'test-results/screens/rays-16x16.png' });

  // Recorded, not asserted: SwiftShader and a busy CI machine make a 50 ms bound unfair.
  mkdirSync('test-results', { recursive: true });
  const metrics = {
    date: new Date().toISOString(),
    firstRaysMs,
    rays8x6: all,
    rays16x16: rays16,
    tracingEdits: { edits: 30, ms: editsMs, longTasks: longTasks.length, maxLongTaskMs: Math.round(Math.max(0, ...longTasks)) },
  };
  writeFileSync('test-results/view-metrics.json', `${JSON.stringify(metrics, null, 2)}\n`);
  console.log(`view metrics: ${JSON.stringify(metrics)}`);

  expect(errors).toEqual([]);
});

test('the ray panel, legend and pixel preview by keyboard', async ({ page }) => {
  await page.goto(PAGE);
  await expect(page.locator('[data-ray-instances]').first()).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 60_000 });

  // A typed value out of range is clamped, and a note says so.
  const transparency = page.locator('rt-slider[name="transparency"]');
  const field = transparency.locator('input[type="text"]');
  await field.fill('250');
  await field.press('Enter');
  await expect(field).toHaveValue('100');
  await expect(transparency.getByRole('status')).toContainText(/0–100/);
  expect(await page.locator('rt-ray-panel').evaluate((panel) => (panel as HTMLElement & { store: Store }).store.state.rays.transparency)).toBe(1);

  // The legend names every kind of ray next to its colour (and the normal), and follows the palette.
  // A shadow ray reaches the light or is blocked; the direction not tested shows only with Shadows off.
  const legend = page.locator('rt-ray-legend');
  for (const name of ['Primary ray', 'Shadow ray — reaches the light', 'Shadow ray — blocked', 'Reflected ray', 'Refracted ray', 'Hit nothing', 'Normal']) {
    await expect(legend.getByText(name, { exact: true })).toBeVisible();
  }
  await expect(legend.locator('li[data-key="untested"]')).toHaveCount(0);
  const swatch = legend.locator('li[data-key="primary"] .swatch');
  await expect(swatch).toHaveCSS('background-color', 'rgb(112, 255, 251)');
  await page.locator('rt-switch[name="colorBlindPalette"] input').check();
  await expect(swatch).toHaveCSS('background-color', 'rgb(86, 180, 233)');
  // Colour by time brings a key of the time colours, from the shutter's opening to its closing, and takes it away.
  const timeKey = legend.locator('[data-key="time"]');
  await expect(timeKey).toHaveCount(0);
  await page.locator('rt-switch[name="colorByTime"] input').check();
  await expect(timeKey).toBeVisible();
  await expect(timeKey).toContainText('shutter opens');
  await expect(timeKey).toContainText('shutter closes');
  await expect(timeKey.locator('.time-ramp')).toHaveCSS('background-image', /^linear-gradient\(90deg, rgb\(68, 1, 84\).*rgb\(253, 231, 37\) 100%\)$/);
  await legend.screenshot({ path: 'test-results/screens/ray-legend-time-key.png' });
  await page.locator('rt-switch[name="colorByTime"] input').uncheck();
  await expect(timeKey).toHaveCount(0);

  // Enter chooses the focused pixel; with one chosen, the arrows step the choice.
  const first = page.getByRole('button', { name: 'Pixel 0, 0', exact: true });
  await first.focus();
  await page.keyboard.press('Enter');
  await expect(first).toHaveAttribute('aria-pressed', 'true');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowDown');
  const moved = page.getByRole('button', { name: 'Pixel 1, 1', exact: true });
  await expect(moved).toHaveAttribute('aria-pressed', 'true');
  await expect(moved).toBeFocused();
  await page.getByRole('button', { name: 'Show all pixels' }).click();
  await expect(moved).toHaveAttribute('aria-pressed', 'false');
});

test('every visualization option can be switched on in the ray panel, and the view shows it', async ({ page }) => {
  const errors: string[] = [];
  page.on('console', (message) => message.type() === 'error' && errors.push(message.text()));
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto(PAGE);
  const view = page.locator('[data-ray-instances]').first();
  await expect(view).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 60_000 });
  const canvas = view.locator('canvas').first();
  const panel = page.locator('rt-ray-panel');
  const rayState = () => panel.evaluate((element) => (element as HTMLElement & { store: Store }).store.state.rays);

  // The thickness, colour and animation groups may be folded away: open them as a student would.
  for (const section of ['rays-radius', 'rays-colour', 'rays-animation']) {
    const group = panel.locator(`rt-panel-section[name="${section}"]`);
    if ((await group.getAttribute('open')) === null) await group.locator('summary').click();
  }

  const before = PNG.sync.read(await canvas.screenshot());
  for (const name of ['hideNegligible', 'dynamicRadius', 'contributionColor', 'animate', 'animatePixelByPixel', 'loop'] as const) {
    await panel.locator(`rt-switch[name="${name}"] input`).check();
    await expect.poll(async () => (await rayState())[name]).toBe(true);
  }
  // One press in the middle of Negligible below's track is exactly 10 %, as level 12 asks.
  const track = panel.locator('rt-slider[name="negligibleThreshold"] input[type="range"]');
  await track.scrollIntoViewIfNeeded();
  const threshold = (await track.boundingBox())!;
  await page.mouse.click(threshold.x + threshold.width / 2, threshold.y + threshold.height / 2);
  await expect.poll(async () => (await rayState()).negligibleThreshold).toBe(0.1);
  for (const [name, typed, expected] of [
    ['negligibleThreshold', '5', 0.05],
    ['minRadius', '3', 0.03],
    ['maxRadius', '0.5', 0.005],
  ] as const) {
    const field = panel.locator(`rt-slider[name="${name}"] input[type="text"]`);
    await field.fill(typed);
    await field.press('Enter');
    await expect.poll(async () => (await rayState())[name]).toBeCloseTo(expected, 6);
  }
  // Thick, contribution-coloured, growing rays: the picture is not the one we started with.
  await page.waitForTimeout(500);
  const after = PNG.sync.read(await canvas.screenshot());
  let changed = 0;
  for (let i = 0; i < after.data.length; i += 4) if (after.data[i] !== before.data[i] || after.data[i + 1] !== before.data[i + 1]) changed++;
  expect(changed / (after.data.length / 4)).toBeGreaterThan(0.01);
  expect(await distinctColours(canvas)).toBeGreaterThan(100);
  expect(errors).toEqual([]);
});
