import { expect, test, type Page } from '@playwright/test';
import { collectErrors, expectStatus, objectOnScreen, panel, state } from './support/game-steps.ts';

// The lab on a phone (390×844, touch), on a tablet (1024×768, touch) and on a laptop at 200 %
// zoom (1366×768 shows 683×384 CSS px): the view has room, the page reflows into one column
// instead of laying panels over each other, nothing is cut off sideways, and on touch screens
// every button of the view is at least 44 px. Level 1 is played by touch on the phone.

type Box = { x: number; y: number; width: number; height: number };
const overlap = (a: Box, b: Box) => a.x < b.x + b.width - 1 && b.x < a.x + a.width - 1 && a.y < b.y + b.height - 1 && b.y < a.y + a.height - 1;

/** The lab's three areas (the view, the tasks, the panels) have room and do not cover each other; no sideways scrolling. */
async function expectLaidOut(page: Page): Promise<void> {
  const areas = [page.getByRole('main'), page.getByRole('complementary', { name: 'Tasks' }), page.getByRole('complementary', { name: 'Scene and settings' })];
  const boxes = await Promise.all(areas.map(async (area) => (await area.boundingBox())!));
  for (const box of boxes) expect(box.width).toBeGreaterThan(200);
  expect(boxes[0]!.height).toBeGreaterThan(250);
  expect([overlap(boxes[0]!, boxes[1]!), overlap(boxes[0]!, boxes[2]!), overlap(boxes[1]!, boxes[2]!)]).toEqual([false, false, false]);
  const width = page.viewportSize()!.width;
  expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(width);
  // The view's buttons stay inside the view and do not cover one another.
  const view = (await page.locator('rt-scene-view').boundingBox())!;
  const buttons = await page.locator('rt-view-toolbar button').evaluateAll((elements) => elements.map((e) => e.getBoundingClientRect()).map(({ x, y, width, height }) => ({ x, y, width, height })));
  for (const button of buttons) expect(button.x >= view.x - 1 && button.x + button.width <= view.x + view.width + 1, JSON.stringify(button)).toBe(true);
  const groups = await page.locator('rt-view-toolbar [role=group], rt-view-toolbar .group').evaluateAll((elements) => elements.map((e) => e.getBoundingClientRect()).map(({ x, y, width, height }) => ({ x, y, width, height })));
  for (const [i, a] of groups.entries()) for (const b of groups.slice(i + 1)) expect(overlap(a, b), `${JSON.stringify(a)} ${JSON.stringify(b)}`).toBe(false);
}

async function expectTouchTargets(page: Page): Promise<void> {
  const sizes = await page.locator('rt-view-toolbar button, [data-command="levels"], [data-command="render-open"]').evaluateAll((elements) => elements.map((e) => Math.min(e.getBoundingClientRect().width, e.getBoundingClientRect().height)));
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

  test('level 1 at 390×844 by touch: taps, a finger drag on the gizmo, the render window on the whole screen; level 2\'s folded ray legend', async ({ page }) => {
    const errors = collectErrors(page);
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).tap();
    await expectLaidOut(page);
    await expectTouchTargets(page);
    await page.screenshot({ path: 'test-results/screens/layout-phone.png' });

    // A task done in the view makes the next one current without scrolling the page: the view stays where the learner looks.
    const pageScroll = () => page.evaluate(() => new Promise<number>((resolve) => requestAnimationFrame(() => resolve(scrollY))));
    const scrollBefore = await pageScroll();
    await page.locator('rt-view-toolbar [data-command="orbit-left"]').tap();
    await expectStatus(page, 'Look around', 'done');
    await expectStatus(page, 'Zoom in', 'current');
    expect(await pageScroll()).toBe(scrollBefore);
    await page.locator('rt-view-toolbar [data-command="zoom-in"]').tap();
    await expectStatus(page, 'Zoom in', 'done');
    expect(await pageScroll()).toBe(scrollBefore);
    expect((await page.getByRole('main').boundingBox())!.y).toBeGreaterThanOrEqual(0);

    // The touch gestures are in the help.
    await page.locator('rt-view-toolbar [data-command="help"]').tap();
    const help = page.getByRole('dialog', { name: 'Keys and gestures of the 3D view' });
    await expect(help).toContainText('One finger');
    await expect(help).toContainText('Pinch');
    await help.getByRole('button', { name: 'Close' }).tap();

    const ball = await objectOnScreen(page, 'ball');
    await page.touchscreen.tap(ball.x, ball.y);
    await expectStatus(page, 'Select the ball', 'done');
    expect(await pageScroll()).toBe(scrollBefore);

    const hex = page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' });
    await hex.tap();
    await hex.fill('#22cc44');
    await hex.press('Enter');
    await expectStatus(page, 'Paint the ball', 'done');

    // Back up to the view; a finger drags the ball by its gizmo.
    await page.getByRole('main').scrollIntoViewIfNeeded();
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
    await page.getByRole('complementary', { name: 'Tasks' }).scrollIntoViewIfNeeded();
    await page.screenshot({ path: 'test-results/screens/layout-phone-level-done.png' });

    // Level 2 draws the camera's rays (level 1 starts without them): the ray legend folds away
    // behind a small button that does not cover the ball; a tap (or Enter) opens it.
    await panel(page).getByRole('button', { name: 'Next level' }).tap();
    await expect(page.getByRole('heading', { name: 'Rays from the camera' })).toBeVisible();
    await page.getByRole('main').scrollIntoViewIfNeeded();
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

test.describe('a tablet', () => {
  test.use({ viewport: { width: 1024, height: 768 }, hasTouch: true });

  test('1024×768 touch: three columns with room, 44 px targets', async ({ page }) => {
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).tap();
    await expectLaidOut(page);
    await expectTouchTargets(page);
    await page.screenshot({ path: 'test-results/screens/layout-tablet.png' });
  });
});

test.describe('200 % zoom', () => {
  // What Chromium lays out at 200 % on a 1366×768 screen: half the CSS pixels, each two device pixels.
  test.use({ viewport: { width: 683, height: 384 }, deviceScaleFactor: 2 });

  test('1366×768 at 200 %: one column that scrolls, nothing covered or cut off', async ({ page }) => {
    await page.goto('./');
    await page.getByRole('button', { name: 'Got it' }).click();
    await expectLaidOut(page);
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200.png' });

    // A task done with a button of the view that is on screen: the next task becomes current, the page does not move.
    await page.evaluate(() => scrollTo(0, 0));
    const orbit = (await page.locator('rt-view-toolbar [data-command="orbit-left"]').boundingBox())!;
    expect(orbit.y + orbit.height).toBeLessThanOrEqual(384);
    await page.mouse.click(orbit.x + orbit.width / 2, orbit.y + orbit.height / 2);
    await expectStatus(page, 'Look around', 'done');
    await expectStatus(page, 'Zoom in', 'current');
    expect(await page.evaluate(() => new Promise<number>((resolve) => requestAnimationFrame(() => resolve(scrollY))))).toBe(0);
    await page.screenshot({ path: 'test-results/screens/layout-zoom-200-task-done.png' });
  });
});
