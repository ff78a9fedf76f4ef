import { expect, type Locator, type Page, test } from '@playwright/test';
import { readFile } from 'node:fs/promises';
import { PNG } from 'pngjs';
import { levelRange, stretchContrast } from '../src/ui/lab/render-window/contrast-stretch.ts';
import type { RtImageCompare } from '../src/ui/lab/render-window/rt-image-compare.ts';
import type { RtRenderWindow } from '../src/ui/lab/render-window/rt-render-window.ts';
import { collectPageErrors } from './support/page-errors.ts';

/** The page with the lab; the header's "Render image" button opens the render window. */
const APP_PAGE = './#free-lab';

let errors: string[] = [];

test.beforeEach(({ page }) => {
  errors = collectPageErrors(page);
});

test.afterEach(() => {
  expect(errors).toEqual([]);
});

async function openRenderWindow(page: Page): Promise<Locator> {
  await page.goto(APP_PAGE);
  await page.getByRole('button', { name: 'Render image' }).click();
  const window = page.locator('rt-render-window');
  await expect(window).toBeVisible();
  return window;
}

async function renderAndWait(window: Locator): Promise<void> {
  await window.getByRole('button', { name: 'Render', exact: true }).click();
  await expect(window.getByTestId('render-status')).toContainText(/Done in [\d.]+ (ms|s)/, { timeout: 60_000 });
}

function imageSize(window: Locator): Promise<[number, number]> {
  return window.evaluate((element: RtRenderWindow) => element.store!.state.scene.settings.imageSize);
}

/** Distinct RGB colours on the ray traced canvas, and its size in pixels. */
function tracedPicture(window: Locator): Promise<{ width: number; height: number; colours: number }> {
  return window.getByRole('img', { name: 'The ray traced image' }).evaluate((canvas: HTMLCanvasElement) => {
    const { data } = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height);
    const colours = new Set<number>();
    for (let i = 0; i < data.length; i += 4) colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    return { width: canvas.width, height: canvas.height, colours: colours.size };
  });
}

/** FNV-1a over RGBA bytes: the same pixels give the same number in the page and in Node. */
function pixelHash(data: ArrayLike<number>): number {
  let hash = 0x811c9dc5;
  for (let i = 0; i < data.length; i++) hash = Math.imul(hash ^ data[i], 0x01000193) >>> 0;
  return hash;
}

/** `png` shrunk to `width` × `height` RGBA: each pixel the mean of the image pixels whose centres it covers. */
function shrink(png: PNG, width: number, height: number): number[] {
  const sums = new Float64Array(width * height * 4);
  const counts = new Float64Array(width * height);
  for (let y = 0; y < png.height; y++) {
    const row = Math.floor(((y + 0.5) * height) / png.height);
    for (let x = 0; x < png.width; x++) {
      const at = row * width + Math.floor(((x + 0.5) * width) / png.width);
      for (let c = 0; c < 4; c++) sums[at * 4 + c] += png.data[(y * png.width + x) * 4 + c];
      counts[at]++;
    }
  }
  return [...sums].map((sum, i) => sum / counts[i >> 2]);
}

/**
 * The largest mean RGB difference along one row or one column of two pictures: a line of
 * pixels missing or doubled where two pieces meet stands out against a small difference of
 * filters spread over the picture.
 */
function worstLineDifference(a: number[], b: number[], width: number, height: number): number {
  const rows = new Float64Array(height);
  const columns = new Float64Array(width);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = (y * width + x) * 4;
      const difference = (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2])) / 3;
      rows[y] += difference / width;
      columns[x] += difference / height;
    }
  }
  return Math.max(...rows, ...columns);
}

test('opening focuses Render; a render draws the picture and reports time and rays per second', async ({ page }) => {
  const window = await openRenderWindow(page);
  await expect(window.getByRole('button', { name: 'Render', exact: true })).toBeFocused();
  await page.keyboard.press('Enter'); // on the focused Render button
  await expect(window.getByTestId('render-status')).toContainText(/Done in [\d.]+ (ms|s): .+ rays, .+ rays per second, on \d+ workers?\./, {
    timeout: 60_000,
  });
  const [width, height] = await imageSize(window);
  // The final picture is painted on the next frame: poll until it is all there.
  await expect.poll(async () => (await tracedPicture(window)).colours).toBeGreaterThan(500);
  expect(await tracedPicture(window)).toMatchObject({ width, height });
  await page.screenshot({ path: 'test-results/screens/render-window.png' });

  await page.keyboard.press('Escape');
  await expect(window).toBeHidden();
});

test('a render started before the image viewer has loaded finishes, and the viewer then opens whole', async ({ page }) => {
  // The viewer's module loads after the first screen; on a slow machine a window can open and
  // render before it has. Hold the module back to make that moment certain.
  await page.route('**/rt-image-compare*', async (route) => {
    await new Promise((resolve) => setTimeout(resolve, 4000));
    await route.continue();
  });
  const window = await openRenderWindow(page);
  expect(await page.evaluate(() => customElements.get('rt-image-compare') === undefined)).toBe(true);
  await window.getByRole('button', { name: 'Render', exact: true }).click();
  await page.keyboard.press('0'); // Fit, before the viewer can do it: nothing happens, and nothing throws
  await expect(window.getByTestId('render-status')).toContainText(/Done in [\d.]+ (ms|s)/, { timeout: 60_000 });
  await page.waitForFunction(() => customElements.get('rt-image-compare') !== undefined, null, { timeout: 30_000 });
  expect(await window.locator('rt-image-compare').evaluate((viewer: RtImageCompare) => viewer.zoom)).toBe('fit');
});

test('Cancel stops a big render and says so', async ({ page }) => {
  const window = await openRenderWindow(page);
  await window.evaluate((element: RtRenderWindow) =>
    element.store!.dispatch({ type: 'settings.changed', changes: { imageSize: [2048, 1536], supersampling: 3 } }),
  );
  await window.getByRole('button', { name: 'Render', exact: true }).click();
  await expect(window.getByText(/^Step \d+ of \d+: .+ \d+(\.\d)? %$/)).toBeVisible({ timeout: 30_000 });
  // Cancelled once part of the picture is painted: on a busy machine the first step's text
  // can show before its first tile is on the canvas.
  await expect.poll(async () => (await tracedPicture(window)).colours, { timeout: 30_000 }).toBeGreaterThan(50);
  await window.getByRole('button', { name: 'Cancel' }).click();
  await expect(window.getByTestId('render-status')).toContainText('Render cancelled.');
  await expect(window.getByTestId('render-status')).toContainText('The image on show is partial');
  await expect(window.getByRole('button', { name: 'Cancel' })).toBeDisabled();
  // The partial picture stays, and can be saved as it was on show, at the image's size.
  await expect.poll(async () => (await tracedPicture(window)).colours).toBeGreaterThan(50);
  const downloading = page.waitForEvent('download');
  await window.getByRole('button', { name: 'Save as PNG' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toMatch(/^ray-tracer-quest-[a-z0-9-]*2048x1536-partial\.png$/);
  const png = PNG.sync.read(await readFile((await download.path())!));
  expect([png.width, png.height]).toEqual([2048, 1536]);
  const colours = new Set<number>();
  for (let i = 0; i < png.data.length; i += 4) colours.add((png.data[i] << 16) | (png.data[i + 1] << 8) | png.data[i + 2]);
  expect(colours.size).toBeGreaterThan(50);
  // Shown whole, it is drawn into a canvas the size of its place on screen; at 100 % into one
  // of the part on screen, a canvas pixel per image pixel, painted again (not stretched from the small one).
  const traced = window.getByRole('img', { name: 'The ray traced image' });
  const box = (await traced.boundingBox())!;
  expect(box.width).toBeLessThan(1366);
  expect(await tracedPicture(window)).toMatchObject({ width: Math.round(box.width), height: Math.round(box.height) });
  await window.getByRole('button', { name: '100 %' }).click();
  await expect.poll(async () => (await traced.boundingBox())!.width).toBeLessThan(1366);
  await expect.poll(async () => (await tracedPicture(window)).width).toBe(Math.round((await traced.boundingBox())!.width));
  await expect.poll(async () => (await tracedPicture(window)).colours).toBeGreaterThan(50);
});

test('the render window stays open when the view changes nothing it covers, and says why when a task needs the 3D view', async ({ page }) => {
  const window = await openRenderWindow(page);
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'settings.changed', changes: { imageSize: [64, 48] } }));
  await renderAndWait(window);
  // A task's view that only chooses a pixel, or a hint on a panel beside the window: the image stays.
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'view.applied', view: { pixel: [1, 1], rays: { hideNoHit: true } } }));
  await page.waitForTimeout(300);
  await expect(window).toBeVisible();
  await expect(window.getByRole('img', { name: 'The ray traced image' })).toBeVisible();
  // A task's view that frames something in 3D needs the view the window covers: it closes, and the toast says so.
  await window.evaluate((element: RtRenderWindow) => {
    const store = element.store!;
    store.dispatch({ type: 'view.applied', view: { frame: [store.state.scene.objects[0].id] } });
  });
  await expect(window).toBeHidden();
  await expect(page.locator('rt-toast')).toContainText('The render window was closed to show the 3D view this task needs. Open it again with Render image.');
  // The message is over the task column, clear of the 3D view (its rays, its pads a hint may ring) and of the panels.
  const message = (await page.locator('rt-toast .toast').first().boundingBox())!;
  const view = (await page.locator('rt-scene-view').boundingBox())!;
  const tasks = (await page.locator('rt-lab .tasks').boundingBox())!;
  expect(message.x).toBeGreaterThanOrEqual(view.x + view.width);
  expect(message.x).toBeGreaterThanOrEqual(tasks.x);
  expect(message.x + message.width).toBeLessThanOrEqual(tasks.x + tasks.width);
  // Opened again, the last image is still there.
  await page.getByRole('button', { name: 'Render image' }).click();
  await expect(window.getByRole('img', { name: 'The ray traced image' })).toBeVisible();
  await expect(window.getByTestId('render-status')).toContainText(/Done in/);
});

test('the header names the size of the image on show; a size past the limit is clamped with the reason', async ({ page }) => {
  const window = await openRenderWindow(page);
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'settings.changed', changes: { imageSize: [64, 48] } }));
  await expect(window.getByTestId('render-size')).toHaveText('64 × 48 pixels');
  await renderAndWait(window);
  const width = page.locator('rt-tracer-panel').getByRole('textbox', { name: 'Image size width' });
  await width.fill('5000');
  await width.press('Enter');
  await expect(page.locator('rt-tracer-panel')).toContainText('Clamped to 1–4096: the tracer renders at most 4096 pixels per side');
  expect(await imageSize(window)).toEqual([4096, 48]);
  // The old image is not shown under the new size: the header keeps its size and names the next one.
  await expect(window.getByTestId('render-size')).toHaveText('64 × 48 pixels; the next render: 4096 × 48');
});

test('zoomed in, the canvas holds the part on screen: exactly the saved pixels there, after a scroll too, and stretched', async ({ page }) => {
  const window = await openRenderWindow(page);
  await renderAndWait(window);
  const downloading = page.waitForEvent('download');
  await window.getByRole('button', { name: 'Save as PNG' }).click();
  const png = PNG.sync.read(await readFile((await (await downloading).path())!));
  const compare = window.locator('rt-image-compare');
  const traced = window.getByRole('img', { name: 'The ray traced image' });
  /** The saved pixels of the part the viewer says the canvas shows, against the canvas's (a hash each). */
  const shownAndSaved = async (change: (rgba: number[]) => number[] = (rgba) => rgba) => {
    const { full, window: part } = await compare.evaluate((element: RtImageCompare) => element.tracedView);
    expect(full).toEqual({ width: png.width, height: png.height }); // a canvas pixel per image pixel
    const saved: number[] = [];
    for (let y = part.y; y < part.y + part.height; y++)
      saved.push(...png.data.subarray((y * png.width + part.x) * 4, (y * png.width + part.x + part.width) * 4));
    const shown = await traced.evaluate((canvas: HTMLCanvasElement) => [...canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data]);
    return { shown: pixelHash(shown), saved: pixelHash(change(saved)), part };
  };
  await window.getByRole('button', { name: '200 %' }).click();
  await expect.poll(async () => (await traced.boundingBox())!.width).toBeLessThan(2 * png.width);
  await expect
    .poll(async () => {
      const { shown, saved } = await shownAndSaved();
      return shown === saved;
    })
    .toBe(true);
  const before = (await shownAndSaved()).part;
  // A scroll down and to the right with the mouse wheel: another part, painted exactly too.
  const frame = window.getByRole('group', { name: 'Image view: scroll with the arrow keys when zoomed in' });
  const area = (await frame.boundingBox())!;
  await page.mouse.move(area.x + area.width / 2, area.y + area.height / 2);
  await page.mouse.wheel(150, 120);
  await expect.poll(async () => (await shownAndSaved()).part.y).toBeGreaterThan(before.y);
  await expect
    .poll(async () => {
      const { shown, saved } = await shownAndSaved();
      return shown === saved;
    })
    .toBe(true);
  // Stretch contrast: the same part with the whole image's levels spread over 0–255.
  await window.getByRole('checkbox', { name: 'Stretch contrast' }).check();
  const range = levelRange(png.data);
  await expect
    .poll(async () => {
      const { shown, saved } = await shownAndSaved((rgba) => [...stretchContrast(rgba, range)]);
      return shown === saved;
    })
    .toBe(true);
  await window.getByRole('checkbox', { name: 'Stretch contrast' }).uncheck();
  await expect
    .poll(async () => {
      const { shown, saved } = await shownAndSaved();
      return shown === saved;
    })
    .toBe(true);
});

test('Stretch contrast stays on across renders of a scene and is off again when another scene is loaded (a new level)', async ({ page }) => {
  const window = await openRenderWindow(page);
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'settings.changed', changes: { imageSize: [64, 48] } }));
  await renderAndWait(window);
  const stretch = window.getByRole('checkbox', { name: 'Stretch contrast' });
  const levels = window.getByRole('status').filter({ hasText: /shown as 0–255/ });
  await stretch.check();
  await expect(levels).toBeVisible();
  await renderAndWait(window);
  await expect(stretch).toBeChecked();
  await expect(levels).toBeVisible();
  // A level opens with its own scene (the game loads it as the free lab's files do): its first render is not stretched.
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'scene.loaded', scene: element.store!.state.scene }));
  await expect(stretch).not.toBeChecked();
  await renderAndWait(window);
  await expect(stretch).not.toBeChecked();
  await expect(levels).toHaveCount(0);
});

test('an image larger than its window is drawn at the size it is shown: the saved file scaled, no seams', async ({ page }) => {
  const window = await openRenderWindow(page);
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'settings.changed', changes: { imageSize: [1600, 1200] } }));
  await renderAndWait(window);
  const traced = window.getByRole('img', { name: 'The ray traced image' });
  const box = (await traced.boundingBox())!;
  const [width, height] = [Math.round(box.width), Math.round(box.height)];
  expect(width).toBeLessThan(1600);
  // Painted (in bands, over a few frames) into a canvas of the box's size.
  await expect.poll(async () => (await tracedPicture(window)).width).toBe(width);
  const downloading = page.waitForEvent('download');
  await window.getByRole('button', { name: 'Save as PNG' }).click();
  const png = PNG.sync.read(await readFile((await (await downloading).path())!));
  const shrunk = shrink(png, width, height);
  await expect
    .poll(async () => {
      const shown = await traced.evaluate((canvas: HTMLCanvasElement) => [...canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data]);
      return worstLineDifference(shown, shrunk, width, height);
    })
    .toBeLessThan(3); // 0.9 seen; a line of wrong pixels would be tens of levels
});

test('Save as PNG downloads exactly the rendered pixels at the image size', async ({ page }) => {
  const window = await openRenderWindow(page);
  await renderAndWait(window);
  const [width, height] = await imageSize(window);
  const downloading = page.waitForEvent('download');
  await window.getByRole('button', { name: 'Save as PNG' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toMatch(new RegExp(`^ray-tracer-quest-[a-z0-9-]*${width}x${height}\\.png$`));
  const png = PNG.sync.read(await readFile((await download.path())!));
  expect([png.width, png.height]).toEqual([width, height]);
  const shown = await window.getByRole('img', { name: 'The ray traced image' }).evaluate((canvas: HTMLCanvasElement) => {
    return [...canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data];
  });
  expect(pixelHash(png.data)).toBe(pixelHash(shown));
});

test('zoom: 200 % shows every pixel as 2 × 2, Fit brings it back', async ({ page }) => {
  const window = await openRenderWindow(page);
  await renderAndWait(window);
  const [width] = await imageSize(window);
  const canvas = window.getByRole('img', { name: 'The ray traced image' });
  // The canvas holds image pixels (the part on screen): screen pixels per canvas pixel is the zoom.
  const zoomOnScreen = () => canvas.evaluate((element: HTMLCanvasElement) => element.getBoundingClientRect().width / element.width);
  const canvasPixelsPerImagePixel = () =>
    window.locator('rt-image-compare').evaluate((element: RtImageCompare) => element.tracedView.full.width / element.imageWidth);
  const fitted = (await canvas.boundingBox())!.width;
  await window.getByRole('button', { name: '200 %' }).click();
  await expect.poll(zoomOnScreen).toBeCloseTo(2, 2);
  expect(await canvasPixelsPerImagePixel()).toBe(1);
  await expect(canvas).toHaveCSS('image-rendering', 'pixelated');
  await window.getByRole('button', { name: 'Zoom out' }).click();
  await expect.poll(zoomOnScreen).toBeCloseTo(1, 2);
  expect(await canvasPixelsPerImagePixel()).toBe(1);
  await window.getByRole('button', { name: 'Fit' }).click();
  await expect.poll(async () => (await canvas.boundingBox())!.width).toBeCloseTo(fitted, 0);
  expect(fitted).toBeLessThan(2 * width);

  // A small image is shown larger than 200 % at Fit: "200 %" would shrink it, so it is not offered.
  await window.evaluate((element: RtRenderWindow) => element.store!.dispatch({ type: 'settings.changed', changes: { imageSize: [32, 24] } }));
  await renderAndWait(window);
  await expect.poll(zoomOnScreen).toBeGreaterThan(2);
  await expect(window.getByRole('button', { name: '200 %' })).toBeDisabled();
  await expect(window.getByRole('button', { name: '200 %' })).toHaveAttribute('title', 'Fit already shows this small image larger than 200 %');
});

test('the slider compares the ray traced image with the raster one, by mouse or keys', async ({ page }) => {
  const window = await openRenderWindow(page);
  await renderAndWait(window);
  await window.getByRole('radio', { name: 'Slider' }).check();
  await expect(window.getByText('Ray traced', { exact: true }).last()).toBeVisible();
  await expect(window.getByText('Rasterized, like the 3D view')).toBeVisible();
  // The raster picture is really there, not an empty canvas.
  const rasterPixels = await window.getByRole('img', { name: 'The raster image from the same camera' }).evaluate((canvas: HTMLCanvasElement) => {
    const { data } = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height);
    let lit = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i + 3] > 0 && data[i] + data[i + 1] + data[i + 2] > 30) lit++;
    return lit / (data.length / 4);
  });
  expect(rasterPixels).toBeGreaterThan(0.3);

  const divider = window.getByRole('slider', { name: 'Divider' });
  await expect(divider).toHaveValue('50');
  await divider.focus();
  await page.keyboard.press('ArrowLeft');
  await expect(divider).toHaveValue('49');
  // Dragging the divider to a quarter of the image.
  const box = (await window.getByRole('img', { name: 'The ray traced image' }).boundingBox())!;
  await page.mouse.move(box.x + box.width * 0.49, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.25, box.y + box.height / 2, { steps: 5 });
  await page.mouse.up();
  await expect(divider).toHaveValue('25');
  await page.screenshot({ path: 'test-results/screens/render-window-slider.png' });
});

test('a render estimated at over a minute waits: a lighter option renders, nothing starts unasked', async ({ page }) => {
  const window = await openRenderWindow(page);
  const tracer = page.locator('rt-tracer-panel');
  for (const [name, value] of [
    ['Supersampling (s), typed value', '8'],
    ['Image size width', '2048'],
    ['Image size height', '1536'],
  ]) {
    const field = tracer.getByRole('textbox', { name });
    await field.fill(value);
    await field.press('Enter');
  }
  await window.getByRole('button', { name: 'Render', exact: true }).click();
  const heavy = window.getByTestId('heavy-render');
  await expect(heavy).toContainText(/would take about \d+ (min|h|days)/);
  await expect(window.getByTestId('render-status')).toHaveCount(0);
  // The mildest lighter supersampling, with its own estimate, starts the render at once.
  const lighter = heavy.getByRole('button', { name: /^Supersampling \d \(about \d+ s\)$/ });
  const chosen = Number((await lighter.textContent())!.match(/Supersampling (\d)/)![1]);
  expect(chosen).toBeLessThan(8);
  await lighter.click();
  await expect(heavy).toHaveCount(0);
  expect(await window.evaluate((element: RtRenderWindow) => element.store!.state.scene.settings.supersampling)).toBe(chosen);
  await expect(window.getByRole('button', { name: 'Cancel' })).toBeEnabled();
  await window.getByRole('button', { name: 'Cancel' }).click();
  await expect(window.getByTestId('render-status')).toContainText('Render cancelled');
});

test('the workers start once the raster picture is read back, or a second later without it', async ({ page }) => {
  const window = await openRenderWindow(page);
  // The render's progress as the window says it: 'starting' until the workers answer.
  const run = (releaseAfterMs: number | null) =>
    window.evaluate(async (element: RtRenderWindow, releaseAfter) => {
      const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));
      let release = () => {};
      // A raster picture read back when the test says so (or never).
      element.rasterSnapshot = (width, height) => new Promise((resolve) => (release = () => resolve(new ImageData(width, height))));
      const phase = () =>
        element.shadowRoot!.querySelector('[data-testid="render-progress"], [data-testid="render-status"]')?.textContent?.trim() ?? 'starting';
      const start = performance.now();
      void element.startRender();
      await element.updateComplete; // the last render's outcome gives way to 'Starting…'
      let whileHeld = '';
      if (releaseAfter !== null) {
        await sleep(releaseAfter);
        whileHeld = phase();
        release();
      }
      while (phase() === 'starting') await sleep(5);
      const startedAfterMs = performance.now() - start;
      while (!/^Done/.test(phase())) await sleep(20);
      return { whileHeld, startedAfterMs };
    }, releaseAfterMs);

  // Held for 600 ms (the free lab's image renders in a fraction of that): nothing traced until released.
  const released = await run(600);
  expect(released.whileHeld).toBe('starting');
  expect(released.startedAfterMs).toBeGreaterThanOrEqual(600);
  // Never read back (a lost GPU): the render starts anyway, after the window's wait.
  const never = await run(null);
  expect(never.startedAfterMs).toBeGreaterThanOrEqual(1000); // RASTER_WAIT_MS
});
