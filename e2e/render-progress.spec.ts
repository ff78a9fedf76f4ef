import { expect, test, type Locator } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { RtRenderWindow } from '../src/ui/lab/render-window/rt-render-window.ts';
import { collectPageErrors } from './support/page-errors.ts';

/**
 * A heavy render as issue 15 found it ("Quick preview…" with no percentage for over a
 * minute): asked to render anyway, the window must show a moving percentage within the
 * first 2 seconds, and the page's long tasks during it are recorded for `npm run bench`
 * (test-results/render-metrics-<project>.json: the page composited on SwiftShader, and on the CPU).
 */

declare global {
  interface Window {
    /** The main thread's long tasks (> 50 ms) from page start: [start, duration] in ms. */
    rtLongTaskSpans: [number, number][];
    /** When the last click reached the page (performance.now()). */
    rtClickedAt: number;
  }
}

let errors: string[] = [];

test.beforeEach(async ({ page }) => {
  errors = collectPageErrors(page);
  await page.addInitScript(() => {
    window.rtLongTaskSpans = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) window.rtLongTaskSpans.push([Math.round(entry.startTime), Math.round(entry.duration)]);
    }).observe({ type: 'longtask', buffered: true });
    document.addEventListener('click', () => (window.rtClickedAt = performance.now()), { capture: true });
  });
});

test.afterEach(() => {
  expect(errors).toEqual([]);
});

/**
 * The lab's scene, made heavy by its image (the largest the schema allows), its depth and
 * 3×3 supersampling: minutes of rendering. Not the heaviest scene itself (256 glass
 * objects, 32 area lights, 8×8 samples): on SwiftShader that tests the 3D view instead,
 * whose first frame after it took 10 s with one light and 142 s with 32, and whose 10k
 * camera rays at 8×8 samples keep the page's GPU busy.
 */
async function makeHeavy(renderWindow: Locator): Promise<void> {
  await renderWindow.evaluate((element: RtRenderWindow) =>
    element.store!.dispatch({ type: 'settings.changed', changes: { maxDepth: 10, supersampling: 3, imageSize: [4096, 4096] } }),
  );
}

/**
 * Every progress text the window showed for `ms` after the page's last click, sampled in
 * the page every 10 ms (Playwright's own round trips slowed to seconds on a loaded machine),
 * with the ms since that click. A long task on the main thread delays the samples, as it
 * delays what the learner sees.
 */
function progressTimeline(renderWindow: Locator, ms: number): Promise<{ at: number; text: string }[]> {
  return renderWindow.evaluate(async (element, duration) => {
    const seen: { at: number; text: string }[] = [];
    const progress = () => element.shadowRoot?.querySelector('[data-testid="render-progress"]');
    for (let at = performance.now() - window.rtClickedAt; at <= duration; at = performance.now() - window.rtClickedAt) {
      const text = progress()?.textContent?.trim() ?? '';
      if (text !== seen.at(-1)?.text) seen.push({ at: Math.round(at), text });
      await new Promise((resolve) => setTimeout(resolve, 10));
    }
    return seen;
  }, ms);
}

test('a heavy render, rendered anyway, shows a moving percentage within 2 s and keeps the page responsive', async ({ page }) => {
  await page.goto('./#free-lab');
  await page.getByRole('button', { name: 'Render image' }).click();
  const renderWindow = page.locator('rt-render-window');
  await expect(renderWindow).toBeVisible();
  await makeHeavy(renderWindow);
  await renderWindow.getByRole('button', { name: 'Render', exact: true }).click();
  await expect(renderWindow.getByTestId('heavy-render')).toContainText(/would take about \d+ (min|h|days)/);

  await renderWindow.getByRole('button', { name: 'Render anyway' }).click();
  const timeline = await progressTimeline(renderWindow, 5000);
  // Long tasks of those 5 s, with their start relative to the click (read before the probes
  // below: reading a canvas's pixels waits for the GPU, a long task of the test's own).
  const longTasks = await page.evaluate(() =>
    window.rtLongTaskSpans
      .filter(([start, duration]) => start + duration > window.rtClickedAt && start < window.rtClickedAt + 5000)
      .map(([start, duration]) => [Math.round(start - window.rtClickedAt), duration]),
  );
  // The picture, not only the percentage: the share of 64 pixels spread over it that are not
  // black (it stayed black for seconds while previews were pasted at full resolution).
  const traced = renderWindow.getByRole('img', { name: 'The ray traced image' });
  const litShare = () =>
    traced.evaluate((canvas: HTMLCanvasElement) => {
      const context = canvas.getContext('2d')!;
      let lit = 0;
      for (let i = 0; i < 64; i++) {
        const [r, g, b, a] = context.getImageData(
          Math.floor((((i % 8) + 0.5) / 8) * canvas.width),
          Math.floor(((Math.floor(i / 8) + 0.5) / 8) * canvas.height),
          1,
          1,
        ).data;
        if (a > 0 && r + g + b > 0) lit++;
      }
      return lit / 64;
    });
  const litAt5s = await litShare();
  // Recorded with the other figures; asserted only as "covered within 20 s" (a loaded machine
  // and SwiftShader's software canvas make any tighter bound unfair).
  await expect.poll(litShare, { timeout: 15_000, message: 'share of the picture that is not black' }).toBeGreaterThanOrEqual(0.75);
  const coveredWithinMs = Math.round(await page.evaluate(() => performance.now() - window.rtClickedAt));
  await page.screenshot({ path: 'test-results/screens/render-heavy-progress.png' });

  // Zoomed to 100 % and scrolled with the wheel while it renders: the canvas holds only the
  // part on screen (a canvas of the image's size had tasks of 200–260 ms here, composited on the CPU).
  await renderWindow.getByRole('button', { name: '100 %' }).click();
  const frame = renderWindow.getByRole('group', { name: 'Image view: scroll with the arrow keys when zoomed in' });
  const area = (await frame.boundingBox())!;
  await page.mouse.move(area.x + area.width / 2, area.y + area.height / 2);
  for (let step = 0; step < 5; step++) {
    await page.mouse.wheel(120, 160);
    await page.waitForTimeout(200);
  }
  await page.waitForTimeout(1000);
  const zoomedLongTasks = await page.evaluate(() =>
    window.rtLongTaskSpans
      .filter(([start, duration]) => start + duration > window.rtClickedAt)
      .map(([start, duration]) => [Math.round(start - window.rtClickedAt), duration]),
  );
  await page.screenshot({ path: 'test-results/screens/render-heavy-zoomed.png' });
  expect(await traced.evaluate((canvas: HTMLCanvasElement) => canvas.width * canvas.height)).toBeLessThan(1366 * 768);

  mkdirSync('test-results', { recursive: true });
  const metrics = {
    date: new Date().toISOString(),
    heavyRender: {
      timeline,
      litShareAt5s: litAt5s,
      coveredWithinMs,
      longTasks,
      maxLongTaskMs: Math.max(0, ...longTasks.map(([, duration]) => duration)),
      zoomedLongTasks,
    },
  };
  writeFileSync(`test-results/render-metrics-${test.info().project.name}.json`, `${JSON.stringify(metrics, null, 2)}\n`);
  console.log(`render metrics: ${JSON.stringify(metrics)}`);

  // Within 2 s of the click: at least two different percentages. (The long tasks are
  // recorded, not asserted: SwiftShader and a busy machine make a 50 ms bound unfair.)
  const percentages = timeline.filter(({ at, text }) => at <= 2000 && /^Step \d+ of \d+: .+ \d+(\.\d)? %$/.test(text));
  expect(new Set(percentages.map(({ text }) => text)).size, JSON.stringify(timeline)).toBeGreaterThanOrEqual(2);

  // The raster picture for the comparison is at most 1024 pixels a side (RASTER_MAX_SIDE).
  const raster = renderWindow.getByRole('img', { name: 'The raster image from the same camera', includeHidden: true });
  await expect.poll(() => raster.evaluate((canvas: HTMLCanvasElement) => [canvas.width, canvas.height])).toEqual([1024, 1024]);
  await renderWindow.getByRole('button', { name: 'Cancel' }).click();
  await expect(renderWindow.getByTestId('render-status')).toContainText('Render cancelled.');
});
