import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import type { LabState } from '../src/lab-state/lab-state.ts';

// The acceleration panel and the boxes in the 3D view, used as a student would in levels
// 15 and 16: switch the boxes on, change the depth (by keys and by typing, also out of
// range), select a pixel and read what its ray tested.

const level16 = JSON.parse(readFileSync(new URL('../levels/16-the-bvh.level.json', import.meta.url), 'utf8'));
const level15 = JSON.parse(readFileSync(new URL('../levels/15-bounding-boxes.level.json', import.meta.url), 'utf8'));

async function state(page: Page): Promise<LabState> {
  return page.evaluate(() => (document.querySelector('rt-lab') as unknown as { store: { state: LabState } }).store.state);
}

async function openLab(page: Page, scene: unknown, errors: string[]): Promise<void> {
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('./#free-lab');
  await expect(page.locator('rt-scene-list').getByRole('option').first()).toBeVisible();
  await page.evaluate((scene) => {
    const store = (document.querySelector('rt-lab') as unknown as { store: { dispatch(action: unknown): string | undefined } }).store;
    const error = store.dispatch({ type: 'scene.loaded', scene });
    if (error) throw new Error(error);
  }, scene);
}

/** How many box edges (line segments / 12) a named part of the BVH layer draws, or null when it is not there. */
async function boxesDrawn(page: Page, name: string): Promise<number | null> {
  return page.evaluate((name) => {
    type Lines = { geometry: { getAttribute(name: string): { count: number } } };
    const view = document.querySelector('rt-lab')!.shadowRoot!.querySelector('rt-scene-view') as unknown as {
      labView: { scene: { getObjectByName(name: string): Lines | undefined } };
    };
    const lines = view.labView.scene.getObjectByName(name);
    return lines ? lines.geometry.getAttribute('position').count / 24 : null;
  }, name);
}

test('show the BVH, change its depth, and read what one ray tested', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, level16.scene, errors);
  const panel = page.locator('rt-bvh-panel');
  await panel.scrollIntoViewIfNeeded();

  const show = panel.getByRole('switch', { name: 'Show the BVH' });
  await show.click();
  expect((await state(page)).bvh.show).toBe(true);
  // Depth 2 (the start): 4 bright boxes and their 3 faint ancestors.
  await expect.poll(() => boxesDrawn(page, 'bvh:hero')).toBe(7);

  // Keys on the slider: Home goes to 0, the whole model.
  const slider = panel.getByRole('slider', { name: 'Depth' });
  await slider.focus();
  await slider.press('Home');
  expect((await state(page)).bvh.depth).toBe(0);
  await expect.poll(() => boxesDrawn(page, 'bvh:hero')).toBe(1);
  await expect(panel.getByText('0 = the whole model. At this depth: 1 box.')).toBeVisible();

  // Typed: 3 gives 8 boxes; 99 is clamped to 20 with a note.
  const field = panel.getByRole('textbox', { name: 'Depth, typed value' });
  await field.fill('3');
  await field.press('Enter');
  expect((await state(page)).bvh.depth).toBe(3);
  await expect(panel.getByText('At this depth: 8 boxes.')).toBeVisible();
  await expect.poll(() => boxesDrawn(page, 'bvh:hero')).toBe(15);
  await field.fill('99');
  await field.press('Enter');
  await expect(panel.locator('rt-slider[name="depth"]').getByRole('status')).toHaveText(/Clamped to 0–20/);
  expect((await state(page)).bvh.depth).toBe(20);

  // One pixel on the character: its ray's tests, far fewer than all 8,624 triangles.
  await expect(panel.getByText('Select a pixel of the camera’s screen to count what its ray tests.')).toBeVisible();
  await page.evaluate(() =>
    (document.querySelector('rt-lab') as unknown as { store: { dispatch(action: unknown): void } }).store.dispatch({ type: 'pixel.selected', pixel: [6, 4] }),
  );
  const counts = panel.locator('.counts');
  await expect(counts).toContainText(/This ray tested \d+ of 8,624 triangles: the BVH skipped 99\.\d\u00a0%\./);
  const tested = Number(await counts.getAttribute('data-triangles'));
  expect(tested).toBeGreaterThan(0);
  expect(tested).toBeLessThan(50);
  await expect(counts).toContainText('The ray hits Character.');

  // Off again: the boxes go.
  await show.press('Space');
  expect((await state(page)).bvh.show).toBe(false);
  await expect.poll(() => boxesDrawn(page, 'bvh:hero')).toBeNull();
  expect(errors).toEqual([]);
});

test('bounding boxes: one per object, and a ray above everything tests no triangle', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, level15.scene, errors);
  const panel = page.locator('rt-bvh-panel');
  await panel.scrollIntoViewIfNeeded();
  await panel.getByRole('switch', { name: 'Show bounding boxes' }).click();
  expect((await state(page)).bvh.showBounds).toBe(true);
  await expect.poll(() => boxesDrawn(page, 'bounds')).toBe(4);

  await page.evaluate(() =>
    (document.querySelector('rt-lab') as unknown as { store: { dispatch(action: unknown): void } }).store.dispatch({ type: 'pixel.selected', pixel: [0, 0] }),
  );
  const counts = panel.locator('.counts');
  await expect(counts).toContainText('This ray tested 0 of 8,624 triangles: it missed the bounding box of every model.');
  await expect(counts).toContainText('its ray tested 4 bounding boxes (one per object) and went through none of them');
  await expect(counts).toContainText('Character: its bounding box was missed, so not one of its triangles was tested.');
  await expect(counts).toContainText('The ray hits nothing.');
  expect(errors).toEqual([]);
});
