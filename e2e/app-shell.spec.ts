import { expect, test } from '@playwright/test';

test('the app shell renders the default scene through the worker pool', async ({ page }) => {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));

  await page.goto('./');
  await expect(page.getByRole('heading', { name: 'Ray Tracer Quest' })).toBeVisible();
  const status = page.getByTestId('render-status');
  await expect(status).toContainText(/Done in [\d.]+ s/, { timeout: 60_000 });

  // The canvas really holds a picture: many distinct colours, not a blank or black frame.
  const picture = await page.locator('rt-app-shell canvas').evaluate((canvas: HTMLCanvasElement) => {
    const { data } = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height);
    const colours = new Set<number>();
    let bright = 0;
    for (let i = 0; i < data.length; i += 4) {
      colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
      if (data[i] + data[i + 1] + data[i + 2] > 150) bright++;
    }
    return { width: canvas.width, height: canvas.height, colours: colours.size, brightShare: bright / (data.length / 4) };
  });
  expect([picture.width, picture.height]).toEqual([512, 384]);
  expect(picture.colours).toBeGreaterThan(500);
  expect(picture.brightShare).toBeGreaterThan(0.3);

  await page.screenshot({ path: 'test-results/screens/app-shell.png', fullPage: true });
  expect(errors).toEqual([]);
});
