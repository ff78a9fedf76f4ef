import { expect, test, type Locator, type Page } from '@playwright/test';
import { collectErrors, current, expectStatus, importProgress, panel, progressFile, state, viewLoaded } from './support/game-steps.ts';

// Level 1, and the shadows level (its pixel, its quiz, its switches, two renders and a lamp to
// move), played with the keyboard alone: every mandatory task earned ("done", not "shown"),
// Tab leaving the 3D view with something selected, and the focus back on the opener when the
// render window, the help and the level map close. Controls are reached with focus() (what
// Tab would do after a few presses) and used with keys only; only the shadows level's setup
// (a progress file that opens it, through the menu) uses the mouse.

/** Where the keyboard focus is, through shadow roots: the element's tag and its data-command or role. */
async function focused(page: Page): Promise<string> {
  return page.evaluate(() => {
    let active = document.activeElement;
    while (active?.shadowRoot?.activeElement) active = active.shadowRoot.activeElement;
    if (!active) return 'nothing';
    return [active.tagName.toLowerCase(), active.getAttribute('data-command') ?? active.getAttribute('role') ?? ''].join(' ').trim();
  });
}

async function press(target: Locator, ...keys: string[]): Promise<void> {
  await target.focus();
  for (const key of keys) await target.page().keyboard.press(key);
}

const canvas = (page: Page) => page.locator('rt-scene-view canvas');
const keyNote = (page: Page) => page.locator('rt-scene-view p.note[role="status"]');

test('level 1 by keyboard only: every mandatory task done, Tab leaves the view, focus comes back from the render window, the help and the map', async ({
  page,
}) => {
  const errors = collectErrors(page);
  await page.goto('./');
  await press(page.getByRole('button', { name: 'Got it' }), 'Enter');

  await viewLoaded(page);
  await press(canvas(page), 'ArrowLeft');
  await expectStatus(page, 'Look around', 'done');
  await page.keyboard.press('+');
  await expectStatus(page, 'Zoom in', 'done');

  // N steps through the scene: the floor, then the ball.
  await page.keyboard.press('n');
  await page.keyboard.press('n');
  await expectStatus(page, 'Select the ball', 'done');

  // With the ball selected, Tab still leaves the view (no focus trap) for the view's toolbar.
  await page.keyboard.press('Tab');
  expect(await focused(page)).not.toBe('canvas img');
  expect((await state(page)).gizmo.space).toBe('world');

  const hex = page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' });
  await hex.focus();
  await hex.fill('#22cc44');
  await page.keyboard.press('Enter');
  await expectStatus(page, 'Paint the ball', 'done');

  // The arrows move the selected ball a step in the gizmo's mode, and say so.
  await expect(current(page)).toContainText('Move the ball');
  await press(canvas(page), 'ArrowRight');
  await expectStatus(page, 'Move the ball', 'done');
  await expect(keyNote(page)).toHaveText('Ball moved 0.1 m. With Shift: 0.5 m.');
  await page.keyboard.press('Shift+ArrowUp');
  expect((await state(page)).scene.objects.find((o) => o.id === 'ball')?.position).toEqual([-0.7, 1, 0]);

  // The optional task too: the box, turned with R and the arrows.
  await page.keyboard.press('n');
  await page.keyboard.press('r');
  await page.keyboard.press('ArrowLeft');
  await expectStatus(page, 'Turn or stretch the box', 'done');
  expect((await state(page)).scene.objects.find((o) => o.id === 'box')?.rotation).toEqual([0, 35, 0]);

  await page.keyboard.press('Escape');
  await expectStatus(page, 'Let go', 'done');

  // The help opens with ? and gives the focus back to the view when closed.
  await page.keyboard.press('?');
  await expect(page.getByRole('dialog', { name: 'Keys and gestures of the 3D view' })).toBeVisible();
  await page.keyboard.press('Escape');
  await expect(page.getByRole('dialog', { name: 'Keys and gestures of the 3D view' })).toBeHidden();
  expect(await focused(page)).toBe('canvas img');

  await press(page.locator('[data-command="render-open"]'), 'Enter');
  // The window opens with the focus on Render: Enter renders, which finishes the task.
  await page.keyboard.press('Enter');
  await expectStatus(page, 'Open the ray tracer', 'done');
  await expect(panel(page).getByText('Level complete!')).toBeVisible();
  for (const task of ['Look around', 'Zoom in', 'Select the ball', 'Paint the ball', 'Move the ball', 'Let go', 'Open the ray tracer']) {
    await expectStatus(page, task, 'done');
  }
  await page.keyboard.press('Escape');
  await expect(page.locator('rt-render-window')).toBeHidden();
  expect(await focused(page)).toBe('button render-open');

  // The level map takes the focus (on the level to continue) and gives it back with Esc.
  await press(page.locator('[data-command="levels"]'), 'Enter');
  await expect(page.locator('rt-level-map')).toBeVisible();
  expect(await focused(page)).toBe('button');
  await page.keyboard.press('Escape');
  await expect(page.locator('rt-level-map')).toHaveCount(0);
  expect(await focused(page)).toBe('button levels');
  await page.screenshot({ path: 'test-results/screens/keyboard-level-1-done.png' });
  expect(errors).toEqual([]);
});

test('the shadows level by keyboard only: a pixel of the camera’s screen with P and the arrows, the quiz, the switches, two renders, the lamp moved', async ({
  page,
}) => {
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(['01-introduction', '02-rays-from-the-camera', '32-match-the-shot', '03-shading']));
  await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map [data-level="04-shadows"]').click();
  await expect(panel(page).getByRole('heading', { name: 'Shadows' })).toBeVisible();

  // No flat preview in this level: the pixel is chosen in the 3D view, 0,0 first, then 2 right and 2 down.
  await viewLoaded(page);
  await press(canvas(page), 'p');
  await expect(keyNote(page)).toContainText('Pixel 0, 0');
  for (const key of ['ArrowRight', 'ArrowRight', 'ArrowDown', 'ArrowDown']) await page.keyboard.press(key);
  expect((await state(page)).selectedPixel).toEqual([2, 2]);
  await done(page, 'shadow-pixel');
  await page.keyboard.press('Escape');
  expect((await state(page)).selectedPixel).toBeNull();

  const quiz = current(page);
  await press(quiz.getByRole('radio', { name: 'It is not traced: nothing tests the way' }), 'Space');
  await press(quiz.getByRole('button', { name: 'Lock in my prediction' }), 'Enter');
  await done(page, 'predict-no-shadows');

  const shadows = page.locator('rt-tracer-panel').getByRole('switch', { name: 'Shadows' });
  await press(shadows, 'Space');
  await done(page, 'shadows-off');
  // Observed: the prediction's answer and why, then Continue, by keyboard too.
  const revealed = page.locator('rt-task-card[data-task="predict-no-shadows"]');
  await expect(revealed).toContainText('and so it is');
  await press(revealed.getByRole('button', { name: 'Continue' }), 'Enter');
  await renderByKeyboard(page, 'render-no-shadows');
  await press(shadows, 'Space');
  await done(page, 'shadows-on');

  // The lamp: N past the three objects, then the arrows move it (Shift: 0.5 m).
  await press(canvas(page), 'n', 'n', 'n', 'n');
  expect((await state(page)).selection).toEqual({ kind: 'light', id: 'lamp' });
  await page.keyboard.press('Shift+ArrowDown');
  await done(page, 'move-lamp');
  expect((await state(page)).scene.lights[0]?.position).toEqual([-2.5, 2.5, 2]);
  await page.keyboard.press('Escape');

  await renderByKeyboard(page, 'hard-edges');
  await expect(panel(page).getByText('Level complete!')).toBeVisible();
});

/** Opens the render window with Enter on the header's button, renders with Enter (the focus is on Render), waits for the task `task` (its id), closes with Esc. */
async function renderByKeyboard(page: Page, task: string): Promise<void> {
  await press(page.locator('[data-command="render-open"]'), 'Enter');
  await expect(page.locator('rt-render-window')).toBeVisible();
  await page.keyboard.press('Enter');
  await done(page, task, 60_000);
  await page.keyboard.press('Escape');
  expect(await focused(page)).toBe('button render-open');
}

/** The task with id `task` is done (earned, not shown). */
async function done(page: Page, task: string, timeout?: number): Promise<void> {
  await expect(page.locator(`rt-task-card[data-task="${task}"]`)).toHaveAttribute('status', 'done', { timeout });
}
