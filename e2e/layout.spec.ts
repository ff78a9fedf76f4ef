import { expect, test, type Page } from '@playwright/test';
import {
  clickToolbar,
  collectErrors,
  current,
  expectRingAround,
  expectStatus,
  importProgress,
  objectOnScreen,
  panel,
  progressFile,
  state,
} from './support/game-steps.ts';

// The lab on a phone (390×844 upright and 844×390 on its side, touch), on a tablet (1024×768,
// touch) and on a laptop at 200 % zoom (1366×768 shows 683×384 CSS px): the 3D view and the
// current task are on screen together without scrolling the page; on a small screen the
// column beside (or below) the view shows the tasks or the panels, chosen by two buttons;
// nothing covers anything else or is cut off sideways, and on touch screens every button of
// the view is at least 44 px. Level 1 is played by touch on the phone.

type Box = { x: number; y: number; width: number; height: number };
const overlap = (a: Box, b: Box) => a.x < b.x + b.width - 1 && b.x < a.x + a.width - 1 && a.y < b.y + b.height - 1 && b.y < a.y + a.height - 1;
const inside = (box: Box, width: number, height: number) => box.x >= 0 && box.y >= 0 && box.x + box.width <= width + 0.5 && box.y + box.height <= height + 0.5;

const tasksArea = (page: Page) => page.getByRole('complementary', { name: 'Tasks' });
const panelsArea = (page: Page) => page.getByRole('complementary', { name: 'Scene and settings' });

/**
 * The lab's areas that are shown have room and do not cover each other; no sideways
 * scrolling. On a wide screen the three (view, tasks, panels); on a small one the view and
 * whichever of the tasks and the panels its column shows, the page not scrolling at all.
 */
async function expectLaidOut(page: Page, shown: 'all' | 'tasks' | 'panels'): Promise<void> {
  const areas = [page.getByRole('main'), ...(shown === 'panels' ? [] : [tasksArea(page)]), ...(shown === 'tasks' ? [] : [panelsArea(page)])];
  if (shown === 'tasks') await expect(panelsArea(page)).toBeHidden();
  if (shown === 'panels') await expect(tasksArea(page)).toBeHidden();
  const boxes = await Promise.all(areas.map(async (area) => (await area.boundingBox())!));
  for (const box of boxes) expect(box.width).toBeGreaterThan(200);
  expect(boxes[0]!.height).toBeGreaterThan(shown === 'all' ? 250 : 200);
  for (const [i, a] of boxes.entries()) for (const b of boxes.slice(i + 1)) expect(overlap(a, b), `${JSON.stringify(a)} ${JSON.stringify(b)}`).toBe(false);
  const { width, height } = page.viewportSize()!;
  expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(width);
  if (shown !== 'all') {
    for (const box of boxes) expect(inside(box, width, height), JSON.stringify(box)).toBe(true);
    expect(await page.evaluate(() => document.documentElement.scrollHeight)).toBeLessThanOrEqual(height);
  }
  // The view's buttons that are shown stay inside the view and do not cover one another, nor the camera's image, the ray legend or the debugger's button.
  const view = (await page.locator('rt-scene-view').boundingBox())!;
  const visibleBoxes = (selector: string) =>
    page.locator(selector).evaluateAll((elements) =>
      elements
        .map((e) => e.getBoundingClientRect())
        .filter((box) => box.width > 0)
        .map(({ x, y, width, height }) => ({ x, y, width, height })),
    );
  const buttons = await visibleBoxes('rt-view-toolbar button');
  for (const button of buttons) expect(button.x >= view.x - 1 && button.x + button.width <= view.x + view.width + 1, JSON.stringify(button)).toBe(true);
  const groups = [
    ...(await visibleBoxes('rt-view-toolbar [role=group], rt-view-toolbar .group, rt-view-toolbar .pads-toggle')),
    ...(await visibleBoxes('rt-screen-preview, .view-legend, rt-ray-debugger:not([open])')),
  ];
  for (const [i, a] of groups.entries()) for (const b of groups.slice(i + 1)) expect(overlap(a, b), `${JSON.stringify(a)} ${JSON.stringify(b)}`).toBe(false);
}

/** The current task's title and text, and the 3D view (at least 320×200), all on screen at once and apart. */
async function expectViewAndCurrentTask(page: Page): Promise<void> {
  const { width, height } = page.viewportSize()!;
  // The task list scrolls its new current task into view in the frame after it renders (rt-quest-panel.ts).
  await expect(async () => {
    const view = (await page.locator('rt-scene-view').boundingBox())!;
    const card = page.locator('rt-task-card[status="current"]');
    const title = (await card.locator('.head .title').boundingBox())!;
    const text = (await card.locator('.body > p').first().boundingBox())!;
    expect(view.width).toBeGreaterThanOrEqual(320);
    expect(view.height).toBeGreaterThanOrEqual(200);
    for (const box of [view, title, text]) expect(inside(box, width, height), JSON.stringify({ box, width, height })).toBe(true);
    expect([overlap(view, title), overlap(view, text)]).toEqual([false, false]);
  }).toPass({ timeout: 5_000 });
}

async function expectTouchTargets(page: Page): Promise<void> {
  const sizes = await page
    .locator('rt-view-toolbar button, [data-command="levels"], [data-command="render-open"], [data-command="show-tasks"], [data-command="show-panels"]')
    .evaluateAll((elements) =>
      elements
        .map((e) => e.getBoundingClientRect())
        .filter((box) => box.width > 0)
        .map((box) => Math.min(box.width, box.height)),
    );
  expect(sizes.length).toBeGreaterThan(5);
  expect(Math.min(...sizes)).toBeGreaterThanOrEqual(44);
}

/** A touch drag (one finger) from `from` by (dx, dy), in steps, as the browser reports a finger. */
async function touchDrag(page: Page, from: { x: number; y: number }, dx: number, dy: number): Promise<void> {
  const cdp = await page.context().newCDPSession(page);
  const point = (share: number) => [{ x: from.x + dx * share, y: from.y + dy * share }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: point(0) });
  for (const share of [0.2, 0.4, 0.6, 0.8, 1]) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: point(share) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

/** A point of the canvas, under none of the view's buttons, where a tap hits nothing in the scene (found with the view's own picking). */
async function emptySpot(page: Page): Promise<{ x: number; y: number }> {
  return page.evaluate(() => {
    const view = document.querySelector('rt-app rt-lab')!.shadowRoot!.querySelector('rt-scene-view') as unknown as {
      labView: { pickAt(x: number, y: number): unknown; canvas: HTMLCanvasElement };
      shadowRoot: ShadowRoot;
    };
    const box = view.labView.canvas.getBoundingClientRect();
    for (let y = box.top + 10; y < Math.min(box.bottom, innerHeight) - 10; y += 8) {
      for (let x = box.left + 10; x < box.right - 10; x += 8) {
        if (view.shadowRoot.elementFromPoint(x, y) === view.labView.canvas && view.labView.pickAt(x, y) === null) return { x, y };
      }
    }
    throw new Error('no empty spot in the view');
  });
}

test.describe('a phone, by touch', () => {
  test.use({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });

  test("level 1 at 390×844 by touch: the view over the tasks or the panels, taps, a finger drag on the gizmo, the render window on the whole screen; level 2's folded ray legend", async ({
    page,
  }) => {
    const errors = collectErrors(page);
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).tap();
    await expectLaidOut(page, 'tasks');
    await expectViewAndCurrentTask(page);
    await expectTouchTargets(page);
    await page.screenshot({ path: 'test-results/screens/layout-phone.png' });

    // The orbit, pan and zoom pads fold behind one button in the small view; a task done with
    // them makes the next one current, in view, and nothing moves the view.
    const viewAt = (await page.getByRole('main').boundingBox())!;
    const pads = page.locator('rt-view-toolbar [data-command="view-pads"]');
    await expect(page.locator('rt-view-toolbar [data-command="orbit-left"]')).toBeHidden();
    await pads.tap();
    await expect(pads).toHaveAttribute('aria-expanded', 'true');
    await page.locator('rt-view-toolbar [data-command="orbit-left"]').tap();
    await expectStatus(page, 'Look around', 'done');
    await expectStatus(page, 'Zoom in', 'current');
    await expectViewAndCurrentTask(page);
    await page.locator('rt-view-toolbar [data-command="zoom-in"]').tap();
    await expectStatus(page, 'Zoom in', 'done');
    await pads.tap();
    await expect(page.locator('rt-view-toolbar [data-command="orbit-left"]')).toBeHidden();
    expect(await page.getByRole('main').boundingBox()).toEqual(viewAt);

    // The touch gestures are in the help.
    await page.locator('rt-view-toolbar [data-command="help"]').tap();
    const help = page.getByRole('dialog', { name: 'Keys and gestures of the 3D view' });
    await expect(help).toContainText('One finger');
    await expect(help).toContainText('Pinch');
    await help.getByRole('button', { name: 'Close' }).tap();

    const ball = await objectOnScreen(page, 'ball');
    await page.touchscreen.tap(ball.x, ball.y);
    await expectStatus(page, 'Select the ball', 'done');
    await expectViewAndCurrentTask(page);

    // The colour is in the panels: the column shows them instead of the tasks, under the same view.
    await page.locator('[data-command="show-panels"]').tap();
    await expectLaidOut(page, 'panels');
    const hex = page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' });
    await hex.tap();
    await hex.fill('#22cc44');
    await hex.press('Enter');
    await page.locator('[data-command="show-tasks"]').tap();
    await expectStatus(page, 'Paint the ball', 'done');
    await expectViewAndCurrentTask(page);

    // A finger drags the ball by its gizmo.
    const at = await objectOnScreen(page, 'ball');
    await touchDrag(page, at, 50, 15);
    await expectStatus(page, 'Move the ball', 'done');
    expect((await state(page)).scene.objects.find((o) => o.id === 'ball')?.position).not.toEqual([-0.8, 0.5, 0]);

    const sky = await emptySpot(page);
    await page.touchscreen.tap(sky.x, sky.y);
    await expectStatus(page, 'Let go', 'done');

    // The level ends on a finished image, not on an open window.
    await page.locator('[data-command="render-open"]').tap();
    await page.locator('rt-render-window button.primary').tap();
    await expect(page.locator('rt-render-window [data-testid="render-status"]')).toContainText('Done in', { timeout: 60_000 });
    await expect(panel(page).getByText('Level complete!')).toBeAttached();
    const window = (await page.locator('rt-render-window').boundingBox())!;
    expect(window).toEqual({ x: 0, y: 0, width: 390, height: 844 });
    await page.screenshot({ path: 'test-results/screens/layout-phone-render-window.png' });
    await page.locator('rt-render-window').getByRole('button', { name: 'Close the render window' }).tap();
    await page.screenshot({ path: 'test-results/screens/layout-phone-level-done.png' });

    // Level 2 draws the camera's rays (level 1 starts without them): the ray legend folds away
    // behind a small button that does not cover the ball; a tap (or Enter) opens it.
    await panel(page).getByRole('button', { name: 'Next level' }).tap();
    await expect(page.getByRole('heading', { name: 'Rays from the camera' })).toBeVisible();
    const legendButton = page.getByRole('button', { name: 'Ray colours' });
    const legend = page.getByRole('list', { name: 'Ray colours' });
    await expect(legendButton).toHaveAttribute('aria-expanded', 'false');
    await expect(legend).toBeHidden();
    const ballAtStart = await objectOnScreen(page, 'ball');
    const folded = (await legendButton.boundingBox())!;
    expect(overlap(folded, { x: ballAtStart.x - 20, y: ballAtStart.y - 20, width: 40, height: 40 }), JSON.stringify({ folded, ballAtStart })).toBe(false);
    await legendButton.tap();
    await expect(legend).toBeVisible();
    await expect(legend).toContainText('Shadow ray');
    await page.screenshot({ path: 'test-results/screens/layout-phone-legend-open.png' });
    await legendButton.tap();
    await expect(legend).toBeHidden();
    await legendButton.focus();
    await page.keyboard.press('Enter');
    await expect(legendButton).toHaveAttribute('aria-expanded', 'true');
    await page.keyboard.press('Enter');
    await expect(legend).toBeHidden();

    expect(errors).toEqual([]);
  });
});

test.describe('a phone on its side', () => {
  test.use({ viewport: { width: 844, height: 390 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });

  test("844×390 by touch: the tasks beside the view, 44 px targets; a level with the camera's image", async ({ page }) => {
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).tap();
    await expectLaidOut(page, 'tasks');
    await expectViewAndCurrentTask(page);
    await expectTouchTargets(page);
    await page.screenshot({ path: 'test-results/screens/layout-phone-landscape.png' });
    // Level 3 (the camera's image over the view, its rays drawn): passed levels 1, 2 and 32 (the chapter's challenge), the first task done.
    await importProgress(page, progressFile(['01-introduction', '02-rays-from-the-camera', '32-match-the-shot']));
    if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').tap();
    await page.locator('rt-level-map [data-level="03-shading"]').tap();
    await expect(page.getByRole('heading', { name: 'Shading' })).toBeVisible();
    await expect(page.locator('rt-screen-preview').getByRole('button', { name: 'Pixel 0, 0', exact: true })).toBeVisible();
    await expectLaidOut(page, 'tasks');
    await current(page).getByRole('button', { name: 'Next' }).tap();
    await expectViewAndCurrentTask(page);
    await page.screenshot({ path: 'test-results/screens/layout-phone-landscape-level-3.png' });
    // Unfolded, the pads take the view's lower part: the camera's image steps aside until they fold again.
    const image = page.locator('rt-screen-preview');
    await page.locator('rt-view-toolbar [data-command="view-pads"]').tap();
    await expect(page.locator('rt-view-toolbar [data-command="orbit-left"]')).toBeVisible();
    await expect(image).toBeHidden();
    await page.locator('rt-view-toolbar [data-command="view-pads"]').tap();
    await expect(image).toBeVisible();
  });
});

test.describe('a tablet', () => {
  test.use({ viewport: { width: 1024, height: 768 }, hasTouch: true });

  test('1024×768 touch: three columns with room, 44 px targets', async ({ page }) => {
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).tap();
    await expectLaidOut(page, 'all');
    await expectTouchTargets(page);
    await page.screenshot({ path: 'test-results/screens/layout-tablet.png' });
  });
});

test.describe('200 % zoom', () => {
  // What Chromium lays out at 200 % on a 1366×768 screen: half the CSS pixels, each two device pixels.
  test.use({ viewport: { width: 683, height: 384 }, deviceScaleFactor: 2 });

  test('1366×768 at 200 %: the view beside the current task, the panels a button away, the hint ring on that button', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).click();
    await expectLaidOut(page, 'tasks');
    await expectViewAndCurrentTask(page);
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200.png' });

    // Tasks done with the view's buttons: each next task is current and on screen beside the view, the page never scrolls.
    await clickToolbar(page, 'view-pads');
    await clickToolbar(page, 'orbit-left');
    await expectStatus(page, 'Look around', 'done');
    await expectStatus(page, 'Zoom in', 'current');
    await expectViewAndCurrentTask(page);
    await clickToolbar(page, 'zoom-in');
    await expectStatus(page, 'Zoom in', 'done');
    await clickToolbar(page, 'view-pads');
    const ball = await objectOnScreen(page, 'ball');
    await page.mouse.click(ball.x, ball.y);
    await expectStatus(page, 'Select the ball', 'done');
    await expectStatus(page, 'Paint the ball', 'current');
    await expectViewAndCurrentTask(page);
    expect(await page.evaluate(() => scrollY)).toBe(0);
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200-task-done.png' });

    // The hint ring for a control of the hidden panels goes around the button that shows them, then around the control.
    await current(page).getByRole('button', { name: 'Hint' }).click();
    await current(page).getByRole('button', { name: 'Another hint' }).click();
    // A message (here the one a closed render window leaves) does not cover the current task's hint buttons.
    await page
      .locator('rt-lab')
      .evaluate((lab: HTMLElement & { toast(text: string): void }) =>
        lab.toast('The render window was closed to show the 3D view this task needs. Open it again with Render image.'),
      );
    const message = (await page.locator('rt-toast .toast').boundingBox())!;
    for (const button of await current(page).getByRole('button').all()) {
      const box = await button.boundingBox();
      if (box) expect(overlap(box, message), JSON.stringify({ box, message })).toBe(false);
    }
    await page.locator('rt-toast').getByRole('button', { name: 'Dismiss message' }).click();
    await current(page).getByRole('button', { name: 'Show me where' }).click();
    const showPanels = page.getByRole('button', { name: 'Scene and settings' });
    await expectRingAround(page, showPanels);
    await showPanels.click();
    await expect(showPanels).toHaveAttribute('aria-pressed', 'true');
    await expectLaidOut(page, 'panels');
    const colour = page.locator('rt-object-panel rt-color-field[name="color"]');
    await expectRingAround(page, colour);
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200-panels.png' });
    const hex = page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' });
    await hex.fill('#22cc44');
    await hex.press('Enter');
    await page.getByRole('button', { name: 'Tasks', exact: true }).click();
    await expectStatus(page, 'Paint the ball', 'done');
    await expectViewAndCurrentTask(page);
    expect(errors).toEqual([]);
  });

  test('the free lab at 200 %: every panel beside the view, its buttons, image and debugger apart', async ({ page }) => {
    await page.goto('./#free-lab');
    await expect(page.locator('rt-screen-preview').getByRole('button', { name: 'Pixel 0, 0', exact: true })).toBeVisible();
    await expectLaidOut(page, 'panels');
    await expect(page.locator('[data-command="show-panels"]')).toBeHidden();
    // The pixel preview's caption is whole inside its card (the grid scrolls instead), also with a pixel chosen.
    const preview = page.locator('rt-screen-preview');
    for (const choose of [false, true]) {
      if (choose) await preview.getByRole('button', { name: 'Pixel 0, 0', exact: true }).click();
      const caption = (await preview.locator('.caption').boundingBox())!;
      const card = (await preview.boundingBox())!;
      expect(caption.height).toBeGreaterThan(10);
      expect(caption.y >= card.y && caption.y + caption.height <= card.y + card.height + 0.5, JSON.stringify({ caption, card })).toBe(true);
    }
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200-free-lab.png' });
  });

  test('the ray debugger at 200 %: it takes the column beside the view, which keeps 320×200; its parts scroll under its step buttons', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('./#free-lab');
    await expect(page.locator('rt-screen-preview').getByRole('button', { name: 'Pixel 0, 0', exact: true })).toBeVisible();
    await page.getByRole('button', { name: 'Debug a pixel' }).click();
    const debuggerPanel = page.locator('rt-ray-debugger');
    const middle = debuggerPanel.getByRole('button', { name: 'Use the middle pixel' });
    if (await middle.isVisible()) await middle.click();
    await expect(debuggerPanel).toHaveAttribute('data-step', '0');
    const { width, height } = page.viewportSize()!;
    const view = (await page.locator('rt-scene-view').boundingBox())!;
    const card = (await debuggerPanel.locator('.card').boundingBox())!;
    expect(view.width).toBeGreaterThanOrEqual(320);
    expect(view.height).toBeGreaterThanOrEqual(200);
    expect(card.width).toBeGreaterThanOrEqual(240);
    expect(inside(card, width, height), JSON.stringify(card)).toBe(true);
    expect(overlap(view, card), JSON.stringify({ view, card })).toBe(false);
    // The view's own buttons stay clear of it.
    for (const button of await page.locator('rt-view-toolbar button').all()) {
      const box = await button.boundingBox();
      if (box && box.width > 0) expect(overlap(box, card), JSON.stringify(box)).toBe(false);
    }
    // The step buttons and Close stay on screen while the parts under them scroll.
    const step = debuggerPanel.getByRole('button', { name: /^Step/ });
    for (let i = 1; i <= 3; i++) {
      await step.click();
      await expect(debuggerPanel).toHaveAttribute('data-step', String(i));
    }
    const columns = debuggerPanel.locator('.columns');
    const scrolls = await columns.evaluate((element) => element.scrollHeight > element.clientHeight);
    expect(scrolls).toBe(true);
    for (const part of [debuggerPanel.locator('rt-debug-tree .running'), debuggerPanel.locator('rt-debug-equation ul.sums')]) {
      await part.evaluate((element) => element.scrollIntoView({ block: 'nearest' }));
      const box = (await part.boundingBox())!;
      const columnsBox = (await columns.boundingBox())!;
      expect(box.y).toBeGreaterThanOrEqual(columnsBox.y - 1);
      expect(box.y + box.height).toBeLessThanOrEqual(columnsBox.y + columnsBox.height + 1);
      for (const control of [step, debuggerPanel.getByRole('button', { name: 'Close', exact: true })]) {
        const at = (await control.boundingBox())!;
        expect(inside(at, width, height) && at.y + at.height <= columnsBox.y + 1, JSON.stringify(at)).toBe(true);
      }
    }
    expect(await page.evaluate(() => document.documentElement.scrollHeight)).toBeLessThanOrEqual(height);
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200-debugger.png' });
    await debuggerPanel.getByRole('button', { name: 'Close', exact: true }).click();
    await expectLaidOut(page, 'panels');
    expect(errors).toEqual([]);
  });
});
