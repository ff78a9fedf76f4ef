import { expect, test } from '@playwright/test';
import { importProgress, progressFile } from './support/game-steps.ts';
const ids = (process.env.LEVELS ?? '04-shadows').split(',');
test('shots', async ({ page }) => {
  test.setTimeout(300_000);
  await page.setViewportSize({ width: 1366, height: 768 });
  await page.goto('./' + (process.env.LANGQ ?? ''));
  await page.getByRole('button', { name: /Got it|Begrepen/ }).click();
  await importProgress(page, progressFile(['01-introduction','02-rays-from-the-camera','03-shading','04-shadows','05-reflections','06-refraction','07-transparent-interactions','08-spot-lights','09-attenuation']));
  for (const id of ids) {
    if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').click();
    await page.locator(`rt-level-map [data-level="${id}"]`).click();
    await expect(page.locator('rt-scene-view')).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 30_000 });
    await page.waitForTimeout(2500);
    await page.screenshot({ path: `/tmp/level-${id}.png` });
  }
});
