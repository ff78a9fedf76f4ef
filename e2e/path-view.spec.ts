import { expect, test, type Locator, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { collectErrors, importProgress, levelsFolder, panel, progressFile, state, viewLoaded } from './support/game-steps.ts';

/**
 * Path mode in the 3D view (issue 42), as a learner meets it in "Better guesses": a pixel
 * chosen with the keyboard draws its sample paths with the debugger closed (the canvas
 * changes, and the view draws the paths' rays), and the path debugger steps along a path,
 * the view following it (the ray into the vertex and the sampling lobe appear), and jumps to
 * a vertex chosen from its list or clicked in the 3D view.
 *
 * It relies on: the level map's data-level, the 3D view's `p` and arrow keys for a pixel,
 * "Debug a pixel", <rt-path-debugger>'s data-vertex, Go to list and trees, the view's
 * projectToView, and rt-lab's services' drawn counts.
 */

const order = (JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] }).chapters.flatMap(
  (chapter) => chapter.levels,
);
const LEVEL = '23-better-guesses';

/** The canvas's picture, once two looks in a row agree (the rays have stopped growing). */
async function settled(canvas: Locator): Promise<Buffer> {
  let last = await canvas.screenshot();
  for (let look = 0; look < 12; look++) {
    await canvas.page().waitForTimeout(150);
    const now = await canvas.screenshot();
    if (now.equals(last)) return now;
    last = now;
  }
  return last;
}

/** Where vertex `vertex` of the path debugger's first path is on the page, as the 3D view projects it (its private trees). */
const vertexOnScreen = (page: Page, vertex: number) =>
  page.evaluate((index) => {
    const lab = document.querySelector('rt-app rt-lab')!.shadowRoot!;
    const view = lab.querySelector('rt-scene-view') as unknown as {
      labView: { projectToView(p: readonly number[]): { x: number; y: number } };
      shadowRoot: ShadowRoot;
    };
    const paths = lab.querySelector('rt-ray-debugger')!.shadowRoot!.querySelector('rt-path-debugger') as unknown as {
      trees: { vertices: { point: number[] }[][] };
    };
    const at = view.labView.projectToView(paths.trees.vertices[0]![index]!.point);
    const box = view.shadowRoot.querySelector('canvas')!.getBoundingClientRect();
    return { x: box.left + at.x, y: box.top + at.y };
  }, vertex);

const drawnRays = (canvas: Locator) =>
  canvas.page().evaluate(() => (document.querySelector('rt-app rt-lab') as unknown as { services: { drawn: { rays: number } } }).services.drawn.rays);

test('path mode: a chosen pixel’s paths drawn in 3D, and the path debugger steps along one', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(order.slice(0, order.indexOf(LEVEL))));
  await page.locator('[data-command="levels"]').click();
  await page.locator(`rt-level-map [data-level="${LEVEL}"]`).click();
  await expect(panel(page).getByRole('heading', { name: 'Better guesses' })).toBeVisible();
  expect((await state(page)).scene.settings.integrator).toBe('path');
  await viewLoaded(page);
  const canvas = page.locator('rt-scene-view canvas');
  const screen = await settled(canvas);
  const screenRays = await drawnRays(canvas);

  // A pixel in the middle of the room, by keyboard: its paths replace the screen's rays.
  await canvas.focus();
  for (const key of ['p', 'ArrowRight', 'ArrowRight', 'ArrowRight', 'ArrowDown', 'ArrowDown', 'ArrowDown']) await page.keyboard.press(key);
  expect((await state(page)).selectedPixel).toEqual([3, 3]);
  // Eight paths: at least a camera ray each, and light samples dashed to the lamp.
  await expect.poll(() => drawnRays(canvas)).toBeGreaterThanOrEqual(16);
  expect(await drawnRays(canvas)).not.toBe(screenRays);
  await expect.poll(async () => (await canvas.screenshot()).equals(screen)).toBe(false);

  // The debugger starts at the camera (nothing cast yet) and steps to the first vertex.
  await page.getByRole('button', { name: 'Debug a pixel' }).click();
  const debuggerPanel = page.locator('rt-path-debugger');
  await expect(debuggerPanel).toHaveAttribute('data-vertex', '0');
  // At the camera nothing is drawn: the next step draws its ray and the lobe at its vertex.
  const atCamera = await canvas.screenshot();
  await page.keyboard.press('ArrowRight');
  await expect(debuggerPanel).toHaveAttribute('data-vertex', '1');
  await expect(debuggerPanel.locator('tr.current td').first()).toHaveText('1');
  await expect.poll(async () => (await canvas.screenshot()).equals(atCamera)).toBe(false);

  // The vertex chosen: from the Go to list (keyboard), then by a click on a drawn vertex in 3D.
  await page.keyboard.press('End');
  const last = Number(await debuggerPanel.getAttribute('data-vertex'));
  expect(last).toBeGreaterThan(1);
  await debuggerPanel.getByRole('combobox', { name: 'Go to' }).selectOption('1');
  await expect(debuggerPanel).toHaveAttribute('data-vertex', '1');
  await page.keyboard.press('End');
  const vertexOne = await vertexOnScreen(page, 1);
  await page.mouse.click(vertexOne.x, vertexOne.y);
  await expect(debuggerPanel).toHaveAttribute('data-vertex', '1');
  expect((await state(page)).selection).toBeNull();
  expect(errors).toEqual([]);
});
