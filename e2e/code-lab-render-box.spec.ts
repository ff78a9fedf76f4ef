import { expect, test } from '@playwright/test';
import { allPassedBut, openCodeTask, typeCode } from './support/code-lab-steps.ts';
import { collectErrors } from './support/game-steps.ts';

// Render with my function in the box lab (level 15): a correct slab test renders the level's
// boxes as the tracer's own test does; one that never swaps a slab's t0 and t1 loses the box
// (its rays go the negative way along an axis), and the difference shows.

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

test('Render with my function draws level 15’s boxes with the learner’s hitBox', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, allPassedBut('15-bounding-boxes'), '15-bounding-boxes', 'code-hit-box');
  const renderButton = lab.getByRole('button', { name: 'Render with my function' });

  await typeCode(page, CORRECT);
  await renderButton.click();
  await expect(lab.getByText('No pixel differs: your function renders the scene as the tracer’s does.')).toBeVisible();

  await typeCode(page, NO_SWAP);
  await renderButton.click();
  const caption = lab.getByText(/^\d+ of 19200 pixels differ\.$/);
  await expect(caption).toBeVisible();
  expect(Number((await caption.textContent())!.split(' ')[0])).toBeGreaterThan(500);
  expect(errors).toEqual([]);
});
