import { expect, test, type Locator, type Page } from '@playwright/test';
import { readdirSync, readFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import {
  clickToolbar,
  closeRenderWindow,
  collectErrors,
  current,
  expectRingAround,
  expectStatus,
  openRayTracer,
  panel,
  objectOnScreen,
  playLevel1UpToTheRayTracer,
  state,
  importProgress,
  progressFile,
  task,
  lockIn,
  lockInNumber,
  continueFromPrediction,
} from './support/game-steps.ts';

// The game as a student plays it: through the buttons, fields and keys of the page. The
// store and the view are only read (state, where the ball is on screen), never driven.

import { levelsFolder } from './support/game-steps.ts';
const index = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
const levelIds = index.chapters.flatMap((chapter) => chapter.levels);

async function distinctColours(locator: Locator): Promise<number> {
  const png = PNG.sync.read(await locator.screenshot());
  const colours = new Set<number>();
  for (let i = 0; i < png.data.length; i += 4) colours.add((png.data[i] << 16) | (png.data[i + 1] << 8) | png.data[i + 2]);
  return colours.size;
}

async function playLevel1(page: Page): Promise<void> {
  await playLevel1UpToTheRayTracer(page);
  await openRayTracer(page);
  // Opening the window is not enough: the task wants an image.
  await expect(current(page)).toContainText('Open the ray tracer');
  await page.locator('rt-render-window button.primary').click();
  await expectStatus(page, 'Open the ray tracer', 'done');
  await expect(panel(page).getByText('Level complete!')).toBeVisible();
  await closeRenderWindow(page);
}

async function playLevel2(page: Page): Promise<void> {
  await expect(panel(page).getByRole('heading', { name: 'Rays from the camera' })).toBeVisible();
  await current(page).getByRole('button', { name: 'Next' }).click();

  // Predict, observe, explain: the verdict waits until the pixel's rays have been seen.
  await lockIn(page, 'It sends a ray from that point toward the lamp');
  await expect(current(page)).toContainText('You predicted: “It sends a ray from that point toward the lamp”.');
  await page.locator('rt-screen-preview [data-index="10"]').click();
  await expectStatus(page, 'One pixel', 'done');
  await continueFromPrediction(page, 'Predict: and then?', undefined, async (card) => {
    await expect(card).toContainText('and so it is');
  });
  await page.locator('rt-screen-preview').getByRole('button', { name: 'Show all pixels' }).click();
  await expectStatus(page, 'All pixels again', 'done');

  await lockIn(page, '48');
  for (const [name, value] of [
    ['Pixel columns', '8'],
    ['Pixel rows', '6'],
  ]) {
    const field = page.locator('rt-tracer-panel').getByRole('textbox', { name: `${name}, typed value` });
    await field.fill(value);
    await field.press('Enter');
  }
  await continueFromPrediction(page, 'Predict: how many rays?');

  // A number prediction, checked by the render's own count.
  await lockInNumber(page, '76 800');
  await openRayTracer(page);
  await page.locator('rt-render-window button.primary').click();
  await expect(panel(page).getByText('Level complete!')).toBeVisible({ timeout: 60_000 });
  await closeRenderWindow(page);
  await continueFromPrediction(page, 'Predict: rays for the render');
}

test('a new player plays levels 1 and 2 through the UI; level 2 opens only after level 1', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  // A newcomer starts in level 1, welcomed.
  await expect(page.getByText('Welcome to Ray Tracer Quest!')).toBeVisible();
  await page.getByRole('button', { name: 'Got it' }).click();

  // Level 2 is locked on the map until level 1's mandatory tasks are done.
  await page.locator('[data-command="levels"]').click();
  const level2 = page.locator('rt-level-map [data-level="02-rays-from-the-camera"]');
  await expect(level2).toHaveAttribute('data-status', 'locked');
  await expect(level2).toHaveAttribute('aria-disabled', 'true');
  await level2.click({ force: true });
  await expect(page.locator('rt-level-map')).toBeVisible();
  await page.locator('rt-level-map [data-level="01-introduction"]').click();

  await playLevel1(page);
  await page.locator('[data-command="levels"]').click();
  await expect(page.locator('rt-level-map [data-level="01-introduction"]')).toHaveAttribute('data-status', 'passed');
  await expect(level2).toHaveAttribute('data-status', 'open');
  await page.locator('rt-level-map [data-level="01-introduction"]').click();
  await panel(page).getByRole('button', { name: 'Next level' }).click();

  await playLevel2(page);
  await expect(page.getByTestId('score')).toContainText('points');
  await page.screenshot({ path: 'test-results/screens/game-level-2-done.png' });
  expect(errors).toEqual([]);
});

test('a drag on the orbit pad selects no text, and a level opens at its title with nothing left selected', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(['01-introduction']));
  await page.locator('rt-level-map [data-level="01-introduction"]').click();
  const selected = () => page.evaluate(() => document.getSelection()?.type ?? 'None');

  // Pressed on the orbit pad and dragged over the task column's text, as a learner missing the button would.
  const pad = (await page.locator('rt-view-toolbar [data-guide="view.orbit-buttons"] .centre').boundingBox())!;
  const title = (await panel(page).locator('h2').boundingBox())!;
  await page.mouse.move(pad.x + pad.width / 2, pad.y + pad.height / 2);
  await page.mouse.down();
  await page.mouse.move(title.x + title.width / 2, title.y + title.height / 2, { steps: 12 });
  await page.mouse.up();
  expect(await selected()).not.toBe('Range');

  // Level 1's column scrolled to its end and some text selected; "Next level" (clicked where
  // it is, without scrolling to it) opens level 2.
  const column = page.getByRole('complementary', { name: 'Tasks' });
  const scrolled = await column.evaluate((element) => {
    element.scrollTop = element.scrollHeight;
    return element.scrollTop;
  });
  expect(scrolled).toBeGreaterThan(0);
  await page.evaluate(() => document.getSelection()!.selectAllChildren(document.body));
  expect(await selected()).toBe('Range');
  await panel(page)
    .getByRole('button', { name: 'Next level' })
    .evaluate((button: HTMLButtonElement) => button.click());
  await expect(panel(page).locator('h2')).toHaveText('Rays from the camera');
  await expect.poll(() => column.evaluate((element) => element.scrollTop)).toBe(0);
  await expect(panel(page).locator('h2')).toBeInViewport();
  expect(await selected()).not.toBe('Range');
  expect(errors).toEqual([]);
});

test('an explained prediction folds to one line that opens again, and the next task is brought into view', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(levelIds.slice(0, levelIds.indexOf('04-shadows'))));
  await page.locator('rt-level-map [data-level="04-shadows"]').click();
  await page.locator('rt-screen-preview').getByRole('button', { name: 'Pixel 2, 2', exact: true }).click();
  await lockIn(page, 'It is not traced: nothing tests the way');
  await page.locator('rt-tracer-panel').getByRole('switch', { name: 'Shadows' }).click();
  await expect(page.locator('rt-task-card[data-task="shadows-off"]')).toHaveAttribute('status', 'done');

  // The learner scrolled the column back to the level's intro while reading the explanation,
  // where the task that comes next is out of sight; Continue.
  const column = page.getByRole('complementary', { name: 'Tasks' });
  await column.evaluate((element) => (element.scrollTop = 0));
  await expect(page.locator('rt-task-card[data-task="render-no-shadows"]')).not.toBeInViewport();
  const predict = page.locator('rt-task-card[data-task="predict-no-shadows"]');
  await continueFromPrediction(page, 'Predict: Shadows off', undefined, async (card) => {
    await expect(card).toContainText('the ray tracer casts no shadow ray at all');
  });

  // Folded: one line of what was expected, no explanation, no choices; the next task in view.
  await expect(current(page)).toContainText('Render the image with');
  await expect(current(page)).toBeInViewport({ ratio: 0.9 });
  const summary = predict.locator('.summary');
  await expect(summary).toHaveText('✓ You expected “It is not traced: nothing tests the way”, and so it is.');
  expect((await summary.boundingBox())!.height).toBeLessThan(24);
  await expect(predict).not.toContainText('the ray tracer casts no shadow ray at all');
  await expect(predict.getByRole('radio')).toHaveCount(0);

  // A click on its title opens it again (without Continue), another folds it.
  const head = predict.getByRole('button', { name: /Predict: Shadows off/ });
  await expect(head).toHaveAttribute('aria-expanded', 'false');
  await head.click();
  await expect(predict).toContainText('the ray tracer casts no shadow ray at all');
  await expect(predict.getByRole('button', { name: 'Continue' })).toHaveCount(0);
  await expect(summary).toHaveCount(0);
  await head.click();
  await expect(summary).toBeVisible();
  expect(errors).toEqual([]);
});

test('a free lab link pasted into the tab the game is open in opens the free lab', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await expect(page.locator('rt-lab')).not.toHaveAttribute('free-lab');
  // Only the fragment changes: the browser loads no page, the game follows it.
  await page.evaluate(() => (location.hash = '#free-lab'));
  await expect(page.locator('rt-lab')).toHaveAttribute('free-lab', '');
  await expect(page.getByRole('heading', { name: 'Free lab' })).toBeVisible();
  await expect(page.locator('rt-scene-list').getByRole('option', { name: /Red ball/ })).toBeVisible();
  // Back to a level: the address stops saying free lab, and the same link works again.
  await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map [data-level="01-introduction"]').click();
  await expect(page.locator('rt-lab')).not.toHaveAttribute('free-lab');
  expect(new URL(page.url()).hash).toBe('');
  await page.evaluate(() => (location.hash = '#free-lab'));
  await expect(page.locator('rt-lab')).toHaveAttribute('free-lab', '');
  expect(errors).toEqual([]);
});

test('the ring stays on its control when the sidebar scrolls', async ({ page }) => {
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  // The free lab shows every panel: the sidebar is long enough to scroll.
  await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map').getByRole('button', { name: 'Free lab' }).click();
  await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map [data-level="01-introduction"]').click();
  await clickToolbar(page, 'orbit-left');
  await clickToolbar(page, 'zoom-in');
  // The view reports a zoom once it settles: wait for the next task before asking for its hint.
  await expect(current(page)).toContainText('Select the ball');
  await current(page).getByRole('button', { name: 'Hint' }).click();
  await current(page).getByRole('button', { name: 'Show me where' }).click();
  const ball = page.getByTestId('guide-ring');
  await expect(ball).toBeVisible();
  await current(page).getByRole('button', { name: 'Show me', exact: true }).click();
  // Paint the ball: the ring goes on the colour field in the sidebar.
  await current(page).getByRole('button', { name: 'Hint' }).click();
  await current(page).getByRole('button', { name: 'Another hint' }).click();
  await current(page).getByRole('button', { name: 'Show me where' }).click();
  const colour = page.locator('rt-object-panel rt-color-field[name="color"]');
  await expectRingAround(page, colour);
  // Shrink the window so the sidebar scrolls, scroll it, and the ring follows.
  await page.setViewportSize({ width: 1024, height: 420 });
  await expectRingAround(page, colour);
  await page.locator('.sidebar').evaluate((element) => element.scrollBy(0, 60));
  await expectRingAround(page, colour);
});

test('progress survives a reload in the middle of a level', async ({ page }) => {
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await clickToolbar(page, 'orbit-left');
  await expectStatus(page, 'Look around', 'done');
  await clickToolbar(page, 'zoom-out');
  await expectStatus(page, 'Zoom in', 'done');
  await page.reload();
  await expect(panel(page).getByRole('heading', { name: 'Introduction' })).toBeVisible();
  await expectStatus(page, 'Look around', 'done');
  await expectStatus(page, 'Zoom in', 'done');
  await expect(current(page)).toContainText('Select the ball');
  await expect(page.getByTestId('score')).toContainText('20 points');
  await expect(page.getByText('Welcome to Ray Tracer Quest!')).toHaveCount(0);
});

/** Clicks the scene object `id` in the 3D view, where it is drawn now (read from the view, not driven). */
async function clickInView(page: Page, id: string): Promise<void> {
  const at = await objectOnScreen(page, id);
  await page.mouse.click(at.x, at.y);
}

/** Types `value` into the number field of the object panel's slider `name` and confirms it. */
async function typeInSlider(page: Page, name: string, value: string): Promise<void> {
  const field = page.locator('rt-object-panel').getByRole('textbox', { name: `${name}, typed value` });
  await field.fill(value);
  await field.press('Enter');
}

const pixel = (page: Page, column: number, row: number) =>
  page.locator('rt-screen-preview').getByRole('button', { name: `Pixel ${column}, ${row}`, exact: true });

async function playLevel3(page: Page): Promise<void> {
  await expect(panel(page).getByRole('heading', { name: 'Shading' })).toBeVisible();
  await expect(current(page)).toContainText('The ray colours');
  await expect(page.locator('rt-ray-panel rt-ray-legend')).toBeVisible();
  await current(page).getByRole('button', { name: 'Next' }).click();

  // Pixels of the camera's screen: the hint ladder rings the very pixel to click.
  await expect(current(page)).toContainText('Facing the lamp');
  await current(page).getByRole('button', { name: 'Hint' }).click();
  await current(page).getByRole('button', { name: 'Another hint' }).click();
  await current(page).getByRole('button', { name: 'Show me where' }).click();
  await expectRingAround(page, pixel(page, 2, 1));
  await pixel(page, 2, 1).click();
  await expectStatus(page, 'Facing the lamp', 'done');
  await pixel(page, 3, 2).click();
  await expectStatus(page, 'A shadow ray', 'done');
  await pixel(page, 2, 2).click();
  // Its title is also in another task's text.
  await expect(page.locator('rt-task-card[data-task="dark-side"]')).toHaveAttribute('status', 'done');
  await page.locator('rt-screen-preview').getByRole('button', { name: 'Show all pixels' }).click();

  // The material sliders: the ball is selected in the view, values typed or set with keys.
  await expect(current(page)).toContainText('No ambient light');
  await clickInView(page, 'ball');
  await expect.poll(async () => (await state(page)).selection).toEqual({ kind: 'object', id: 'ball' });
  await typeInSlider(page, 'Ambient (ka)', '0');
  await expectStatus(page, 'No ambient light', 'done');

  // A picture prediction: three renders of the ball drawn by the tracer; the learner picks one.
  const pictures = current(page).locator('rt-quiz canvas');
  await expect(pictures).toHaveCount(3);
  await expect.poll(() => distinctColours(pictures.first()), { timeout: 30_000 }).toBeGreaterThan(20);
  await lockIn(page, 'picture A');
  await typeInSlider(page, 'Shininess (n)', '200');
  await expectStatus(page, 'Polish the ball', 'done');
  const shine = task(page, 'Predict: more shine');
  // Whichever picture A was for this learner, the explanation comes after the observation.
  if (await shine.getByText('What do you see?').isVisible()) {
    await shine.getByRole('radio').first().check();
    await shine.getByRole('button', { name: 'This is what I see' }).click();
  }
  await continueFromPrediction(page, 'Predict: more shine');

  // A wrong prediction is met with "what do you see?" before the answer and why.
  await lockIn(page, 'twice as brightly as before');
  const slant = current(page);
  await expect(slant).toContainText('You predicted: “twice as brightly as before”.');
  for (let rung = 0; rung < 6; rung++) {
    const ladder = slant.locator('rt-hint-box button[data-hint]');
    const kind = await ladder.getAttribute('data-hint');
    await ladder.click();
    if (kind === 'show-me') break;
  }
  await expectStatus(page, 'Light at a slant', 'shown');
  await continueFromPrediction(page, 'Predict: a tilted card', 'half as brightly as before', async (card) => {
    await expect(card).toContainText('You expected “twice as brightly as before”; the answer is “half as brightly as before”.');
    await expect(card).toContainText('You saw: “half as brightly as before”.');
  });
  expect((await state(page)).scene.objects.find((o) => o.id === 'ball')?.material).toMatchObject({ ambient: 0, shininess: 200 });

  await openRayTracer(page);
  await page.locator('rt-render-window button.primary').click();
  await expect(panel(page).getByText('Level complete!')).toBeVisible({ timeout: 60_000 });
  await expectStatus(page, 'Render the polished ball', 'done');
  await closeRenderWindow(page);
}

test('level 3 is played to the end through the UI: pixels, sliders by typing and keys, a quiz, a render', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(['01-introduction', '02-rays-from-the-camera', '32-match-the-shot']));
  await page.locator('[data-command="levels"]').click();
  await expect(page.locator('rt-level-map [data-level="04-shadows"]')).toHaveAttribute('data-status', 'locked');
  await page.locator('rt-level-map [data-level="03-shading"]').click();
  await playLevel3(page);
  await page.locator('[data-command="levels"]').click();
  await expect(page.locator('rt-level-map [data-level="03-shading"]')).toHaveAttribute('data-status', 'passed');
  await expect(page.locator('rt-level-map [data-level="04-shadows"]')).toHaveAttribute('data-status', 'open');
  expect(errors).toEqual([]);
});

test('every level of levels/index.json loads from the map without errors, and its scene draws', async ({ page }) => {
  test.setTimeout(60_000 + levelIds.length * 15_000);
  expect(readdirSync(levelsFolder).length).toBeGreaterThan(1);
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  // Import a file that opens every level, as a learner continuing on another computer would.
  await importProgress(page, progressFile(levelIds));
  for (const id of levelIds) {
    if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').click();
    const entry = page.locator(`rt-level-map [data-level="${id}"]`);
    await expect(entry, `${id} on the map`).not.toHaveAttribute('data-status', /locked|broken/);
    await entry.click();
    await expect(panel(page).locator('h2')).toBeVisible();
    await expect.poll(async () => (await state(page)).scene.name).toBeTruthy();
    await page.waitForTimeout(500);
    expect(await distinctColours(page.locator('rt-scene-view canvas')), `${id} draws its scene`).toBeGreaterThan(100);
  }
  expect(errors).toEqual([]);
});

test('a damaged save: a message, the old data kept, the game goes on', async ({ page }) => {
  // Damaged before the app starts (a running app saves on leaving, over anything written meanwhile).
  await page.addInitScript(() => {
    if (sessionStorage.getItem('damaged')) return;
    sessionStorage.setItem('damaged', 'yes');
    localStorage.setItem('rtq.progress', '{"kind": "ray-tracer-quest-progress", broken');
  });
  await page.goto('./');
  await expect(page.locator('rt-toast')).toContainText('The saved data as it was is kept: download or restore it from the Menu (Damaged saves).');
  await expect(panel(page).getByRole('heading', { name: 'Introduction' })).toBeVisible();
  const keys = await page.evaluate(() => Object.keys(localStorage));
  expect(keys.some((key) => key.startsWith('rtq.progress.backup.'))).toBe(true);
});
