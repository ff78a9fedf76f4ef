import { readdirSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { collectErrors, progressFile } from './support/game-steps.ts';

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

const levelsFolder = new URL('../levels/', import.meta.url);
const ALL_LEVELS = readdirSync(levelsFolder)
  .filter((file) => file.endsWith('.level.json'))
  .map((file) => file.replace('.level.json', ''));

test('Render with my function draws level 15’s boxes with the learner’s hitBox', async ({ page }) => {
  const errors = collectErrors(page);
  await page.addInitScript((saved) => {
    if (window !== window.top || sessionStorage.getItem('seeded')) return;
    sessionStorage.setItem('seeded', 'yes');
    localStorage.setItem('rtq.progress', saved);
  }, progressFile(ALL_LEVELS));
  await page.goto('/');
  const welcome = page.getByRole('button', { name: 'Got it' });
  if (await welcome.count()) await welcome.click();
  await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map [data-level="15-bounding-boxes"]').click();
  await page.locator('rt-task-card[data-task="code-hit-box"] button.head').click();
  const lab = page.locator('rt-code-lab');
  const renderButton = lab.getByRole('button', { name: 'Render with my function' });
  const typeCode = async (code: string) => {
    await lab.locator('.cm-content').click();
    await page.keyboard.press('ControlOrMeta+a');
    await page.keyboard.insertText(code);
  };

  await typeCode(CORRECT);
  await renderButton.click();
  await expect(lab.getByText("No pixel differs: your function renders the scene as the tracer's does.")).toBeVisible();

  await typeCode(NO_SWAP);
  await renderButton.click();
  const caption = lab.getByText(/^\d+ of 19200 pixels differ\.$/);
  await expect(caption).toBeVisible();
  expect(Number((await caption.textContent())!.split(' ')[0])).toBeGreaterThan(500);
  expect(errors).toEqual([]);
});
