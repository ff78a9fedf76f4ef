import { expect, type Page, test } from '@playwright/test';
import type { LabState } from '../src/lab-state/lab-state.ts';
import type { Vec3 } from '../src/scene/scene.ts';
import type { RtSceneView } from '../src/ui/lab/rt-scene-view.ts';

// Level 32 lets the learner move only the ball (ui.movable): the box is clicked in the 3D
// view, says why it stays, and a drag on it orbits the view instead of moving it.

const BOX: Vec3 = [0.9, 0.4, -0.5];

async function open(page: Page, locale: 'en' | 'nl'): Promise<void> {
  await page.goto(`./?lang=${locale}#/preview/32-match-the-shot`);
  const view = page.locator('rt-scene-view');
  await expect.poll(() => view.evaluate((element: RtSceneView) => element.labView?.frameCount ?? 0)).toBeGreaterThan(0);
}

function appState(page: Page): Promise<LabState> {
  return page.locator('rt-scene-view').evaluate((element: RtSceneView) => element.store!.state);
}

async function onPage(page: Page, point: Vec3): Promise<{ x: number; y: number }> {
  const box = (await page.locator('rt-scene-view canvas').boundingBox())!;
  const at = await page.locator('rt-scene-view').evaluate((element: RtSceneView, p) => element.labView!.projectToView(p), point);
  expect(at).not.toBeNull();
  return { x: box.x + at!.x, y: box.y + at!.y };
}

for (const [locale, reason] of [
  ['en', 'Box is locked in this level: you can move only Ball.'],
  ['nl', 'Doos zit vast in dit level: je kunt alleen Bal verplaatsen.'],
] as const) {
  test(`level 32 (${locale}): the clicked box is locked, says why, and a drag does not move it`, async ({ page }) => {
    await open(page, locale);
    const box = await onPage(page, BOX);
    await page.mouse.click(box.x, box.y);
    await expect.poll(async () => (await appState(page)).selection).toEqual({ kind: 'object', id: 'box' });
    await expect(page.locator('rt-scene-view').getByRole('status').filter({ hasText: reason })).toBeVisible();
    await expect(page.locator('rt-scene-list').getByText(reason)).toBeVisible();
    // The note covers none of the view's pads and their captions.
    const note = (await page.locator('rt-scene-view p.note[role="status"]').boundingBox())!;
    const pads = await page
      .locator('rt-view-toolbar .group.pad')
      .evaluateAll((groups) => groups.map((group) => group.getBoundingClientRect().toJSON() as DOMRect));
    expect(pads.length).toBe(3);
    for (const pad of pads) expect(note.y + note.height <= pad.y || note.x + note.width <= pad.x || note.x >= pad.x + pad.width).toBe(true);
    await page.screenshot({ path: `test-results/screens/locked-box-${locale}.png` });

    const before = (await appState(page)).scene;
    await page.mouse.move(box.x, box.y);
    await page.mouse.down();
    await page.mouse.move(box.x + 60, box.y - 30, { steps: 8 });
    await page.mouse.up();
    expect((await appState(page)).scene).toEqual(before);
  });
}
