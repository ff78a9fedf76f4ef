import { expect, test } from '@playwright/test';
import { state } from './support/game-steps.ts';

// The rays' palette is a setting of the menu in every level, kept with the progress across a
// reload; the legend shows each ray type's dash pattern as well as its colour.

test('the colour-blind-safe palette is chosen in the menu, kept after a reload, and the legend shows the dashes', async ({ page }) => {
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await page.getByRole('button', { name: 'Menu' }).click();
  const menu = page.locator('rt-progress-menu');
  await expect(menu.getByRole('radio', { name: 'Standard' })).toBeChecked();
  await menu.getByRole('radio', { name: 'Colour-blind safe' }).check();
  await expect.poll(async () => (await state(page)).rays.colorBlindPalette).toBe(true);

  await page.reload();
  await expect(page.locator('rt-task-card').first()).toBeVisible();
  expect((await state(page)).rays.colorBlindPalette).toBe(true);
  await page.getByRole('button', { name: 'Menu' }).click();
  await expect(menu.getByRole('radio', { name: 'Colour-blind safe' })).toBeChecked();
  await page.keyboard.press('Escape');

  // The free lab's ray panel: its switch shows the same choice, the legend the dashes.
  await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map').getByRole('button', { name: 'Free lab' }).click();
  await expect(page.locator('rt-switch[name="colorBlindPalette"] input')).toBeChecked();
  const legend = page.locator('rt-ray-legend');
  await legend.scrollIntoViewIfNeeded();
  const refract = await legend.locator('li[data-key="refract"] .swatch').evaluate((swatch) => getComputedStyle(swatch).backgroundImage);
  const light = await legend.locator('li[data-key="light"] .swatch').evaluate((swatch) => getComputedStyle(swatch).backgroundImage);
  expect(refract).toContain('repeating-linear-gradient');
  expect(light).toBe('none');
  await legend.screenshot({ path: 'test-results/screens/ray-legend-colour-blind.png' });
  await page.screenshot({ path: 'test-results/screens/rays-colour-blind.png' });
});
