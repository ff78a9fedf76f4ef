import { expect, test, type Locator, type Page } from '@playwright/test';
import { expectAccessible } from './support/axe.ts';
import { allPassedBut, openCodeTask, typeCode } from './support/code-lab-steps.ts';
import { collectErrors } from './support/game-steps.ts';

// Render with my function in the box lab (level 15): a correct slab test renders the level's
// boxes as the tracer's own test does, from the level's camera and from straight above; one
// that never swaps a slab's t0 and t1 loses the box (its rays go the negative way along an
// axis), and the difference shows. One that takes every ray parallel to a slab for a miss
// renders the level's view like a correct one (none of its rays has a zero component) but
// loses the box from above, where every ray goes straight down.

const CORRECT = `function hitBox(origin, direction, boxMin, boxMax) {
  let near = -Infinity;
  let far = Infinity;
  for (const a of ['x', 'y', 'z']) {
    const t0 = (boxMin[a] - origin[a]) / direction[a];
    const t1 = (boxMax[a] - origin[a]) / direction[a];
    near = Math.max(near, Math.min(t0, t1));
    far = Math.min(far, Math.max(t0, t1));
  }
  if (!(near <= far) || far <= 0) return null;
  return near > 0 ? near : far;
}`;

const NO_SWAP = CORRECT.replace('Math.min(t0, t1)', 't0').replace('Math.max(t0, t1)', 't1');

const PARALLEL_MISSES = CORRECT.replace("for (const a of ['x', 'y', 'z']) {", "for (const a of ['x', 'y', 'z']) {\n    if (direction[a] === 0) return null;");

const SAME = 'No pixel differs: your function renders the scene as the tracer’s does.';
const DIFFER = /^\d+ of 19200 pixels differ\.$/;

/** How many of a canvas's pixels are not black. */
const lit = (canvas: Locator) =>
  canvas.evaluate((element) => {
    const c = element as HTMLCanvasElement;
    const data = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
    let count = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] + data[i + 1] + data[i + 2] > 0) count++;
    return count;
  });

const count = async (caption: Locator) => Number((await caption.textContent())!.split(' ')[0]);

/** Level 15's code task opened: its lab, its button, and the view from above with its pictures. */
async function openBoxLab(page: Page) {
  const lab = await openCodeTask(page, allPassedBut('15-bounding-boxes'), '15-bounding-boxes', 'code-hit-box');
  const fromAbove = lab.getByRole('region', { name: 'Rays straight along an axis' });
  return {
    lab,
    renderButton: lab.getByRole('button', { name: 'Render with my function' }),
    fromAbove,
    aboveMine: fromAbove.getByRole('img', { name: 'The scene seen from straight above, rendered with your function.' }),
    aboveDifference: fromAbove.getByRole('img', { name: /^The difference between the two pictures from above/ }),
  };
}

test('a correct hitBox renders level 15 as the tracer does, from the level’s camera and from above', async ({ page }) => {
  // Two views of 19 200 rays, each asked of the sandbox, then axe in two themes: about a minute on a busy 2-core machine.
  test.slow();
  const errors = collectErrors(page);
  const { lab, renderButton, fromAbove, aboveMine, aboveDifference } = await openBoxLab(page);

  await typeCode(page, CORRECT);
  await renderButton.click();
  // Both views: the level's and the one from above.
  await expect(lab.getByText(SAME)).toHaveCount(2);
  await expect(fromAbove.getByText(SAME)).toBeVisible();
  await expect(fromAbove.getByText(/parallel to the x slab and to the z slab/)).toBeVisible();
  // The view from above shows the scene (floor, ball, crate), and no difference.
  expect(await lit(aboveMine)).toBeGreaterThan(160 * 120 * 0.9);
  expect(await lit(aboveDifference)).toBe(0);
  await expectAccessible(page, 'the box lab with its two views');
  expect(errors).toEqual([]);
});

test('a hitBox wrong for parallel rays shows only from above; one that never swaps shows from the level’s camera', async ({ page }) => {
  const errors = collectErrors(page);
  const { lab, renderButton, fromAbove, aboveDifference } = await openBoxLab(page);

  await typeCode(page, PARALLEL_MISSES);
  await renderButton.click();
  const aboveCaption = fromAbove.getByText(DIFFER);
  await expect(aboveCaption).toBeVisible();
  // The level's view, first, has no ray parallel to a slab: it renders as a correct function does.
  await expect(lab.getByText(SAME)).toHaveCount(1);
  await expect(fromAbove.getByText(SAME)).toHaveCount(0);
  const missing = await count(aboveCaption);
  // The crate seen from above is 0.8 m square, about 28 × 28 pixels, all lost.
  expect(missing).toBeGreaterThan(500);
  expect(await lit(aboveDifference)).toBe(missing);

  await typeCode(page, NO_SWAP);
  await renderButton.click();
  await expect(lab.getByText(DIFFER)).toHaveCount(2);
  // The level's caption comes before the view from above.
  expect(await count(lab.getByText(DIFFER).first())).toBeGreaterThan(500);
  expect(errors).toEqual([]);
});
