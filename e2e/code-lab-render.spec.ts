import { expect, test, type Locator } from '@playwright/test';
import { expectAccessible } from './support/axe.ts';
import { allPassedBut, CORRECT_HIT_SPHERE as CORRECT, openCodeTask, typeCode } from './support/code-lab-steps.ts';
import { collectErrors, progressFile } from './support/game-steps.ts';

// Render with my function (spec/code-labs.md §1): the ray–sphere lab's level rendered with a
// correct hitSphere matches the tracer's picture pixel for pixel; one that takes the
// discriminant's sign the wrong way round draws a different picture, and the difference shows.

const LEVEL = '02-rays-from-the-camera';

// The discriminant as 4ac − b²: a hit is taken for a miss and a miss for a hit.
const SIGN_FLIPPED = CORRECT.replace('const d = b * b - 4 * a * c;', 'const d = 4 * a * c - b * b;');

/** A canvas's pixels as drawn: how many differ from black, and how many colours there are. */
const drawn = (canvas: Locator) =>
  canvas.evaluate((element) => {
    const c = element as HTMLCanvasElement;
    const data = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
    let lit = 0;
    const colours = new Set<number>();
    for (let i = 0; i < data.length; i += 4) {
      if (data[i] + data[i + 1] + data[i + 2] > 0) lit++;
      colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
    }
    return { lit, colours: colours.size, pixels: c.width * c.height };
  });

test('Render with my function draws the scene with the learner’s hitSphere beside the tracer’s, and the difference', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, progressFile(['01-introduction']), LEVEL, 'code-hit-sphere');
  const renderButton = lab.getByRole('button', { name: 'Render with my function' });
  await expect(renderButton).toBeVisible();
  const mine = lab.getByRole('img', { name: 'The level’s scene rendered with your function.' });
  const reference = lab.getByRole('img', { name: 'The level’s scene rendered with the tracer’s own function, the reference.' });
  const difference = lab.getByRole('img', { name: /^The difference between the two pictures/ });

  await typeCode(page, CORRECT);
  // Reached by keyboard: focus the button and press Enter.
  await renderButton.focus();
  await page.keyboard.press('Enter');
  await expect(lab.getByText('No pixel differs: your function renders the scene as the tracer’s does.')).toBeVisible();
  const right = await drawn(mine);
  // The scene is there: most pixels lit, in many colours (floor, ball, shading), and the same as the reference's.
  expect(right.lit).toBeGreaterThan(right.pixels / 2);
  expect(right.colours).toBeGreaterThan(50);
  expect(await drawn(reference)).toEqual(right);
  expect((await drawn(difference)).lit).toBe(0);
  // The whole page with a long function in the editor (its box scrolls) and the three pictures.
  await expectAccessible(page, 'the code lab with its three pictures');

  await typeCode(page, SIGN_FLIPPED);
  await renderButton.click();
  await expect(lab.getByText(/^\d+ of 19200 pixels differ\.$/)).toBeVisible();
  const caption = await lab.getByText(/^\d+ of 19200 pixels differ\.$/).textContent();
  const differing = Number(caption!.split(' ')[0]);
  expect(differing).toBeGreaterThan(500);
  // The difference picture lights exactly the pixels the caption counts.
  expect((await drawn(difference)).lit).toBe(differing);
  expect((await drawn(reference)).colours).toBe(right.colours);
  expect(await drawn(mine)).not.toEqual(right);
  expect(errors).toEqual([]);
});

// The samples lab (level 11): its function is random, so a correct one does not draw the
// tracer's picture pixel for pixel; the pictures are compared by eye, not counted. All 16 points
// at the pixel's centre draw stair-stepped edges, far from the tracer's 4 × 4 jittered ones.

const JITTERED = `function pixelSamples(n, random) {
  const cells = Math.round(Math.sqrt(n));
  const points = [];
  for (let j = 0; j < cells; j++)
    for (let i = 0; i < cells; i++) points.push({ x: (i + random()) / cells, y: (j + random()) / cells });
  return points;
}`;

const ALL_AT_CENTRE = `function pixelSamples(n, random) {
  return Array.from({ length: n }, () => ({ x: 0.5, y: 0.5 }));
}`;

/** The mean difference per channel (0..255) between two canvases' pixels. */
const meanDifference = async (a: Locator, b: Locator) => {
  const pixels = (canvas: Locator) =>
    canvas.evaluate((element) => {
      const c = element as HTMLCanvasElement;
      return [...c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data];
    });
  const [p, q] = [await pixels(a), await pixels(b)];
  let sum = 0;
  for (let i = 0; i < p.length; i += 4) for (let c = 0; c < 3; c++) sum += Math.abs(p[i + c]! - q[i + c]!);
  return sum / ((p.length / 4) * 3);
};

test('Render with my function in the samples lab shows the learner’s points per pixel beside the tracer’s, without a pixel count', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, allPassedBut('11-anti-aliasing'), '11-anti-aliasing', 'code-jittered-samples');
  const renderButton = lab.getByRole('button', { name: 'Render with my function' });
  const mine = lab.getByRole('img', { name: 'The level’s scene rendered with your function.' });
  const reference = lab.getByRole('img', { name: 'The level’s scene rendered with the tracer’s own function, the reference.' });
  const compare = lab.getByText(/^Compare the edges: with one random point in each of the 4 × 4 cells/);

  await typeCode(page, JITTERED);
  await renderButton.click();
  await expect(compare).toBeVisible({ timeout: 30_000 });
  await expect(lab.getByText(/pixels differ/)).toHaveCount(0);
  expect((await drawn(mine)).colours).toBeGreaterThan(50);
  const correct = await meanDifference(mine, reference);
  await expectAccessible(page, 'the samples lab with its pictures');

  await typeCode(page, ALL_AT_CENTRE);
  await renderButton.click();
  await expect(lab.getByText('Rendering the scene with your function…')).toBeVisible();
  await expect(compare).toBeVisible({ timeout: 30_000 });
  const wrong = await meanDifference(mine, reference);
  // Measured: 0.29 of 255 for a jittered set against the tracer's, 1.5 for the centre.
  expect(correct).toBeGreaterThan(0);
  expect(wrong).toBeGreaterThan(2 * correct);
  expect(errors).toEqual([]);
});
