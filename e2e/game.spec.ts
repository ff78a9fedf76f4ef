import { expect, test, type Locator, type Page } from '@playwright/test';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import type { AppState } from '../src/app/app-state.ts';

// The game as a student plays it: through the buttons, fields and keys of the page. The
// store and the view are only read (state, where the ball is on screen), never driven.

const levelsFolder = new URL('../levels/', import.meta.url);
const index = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
const levelIds = index.chapters.flatMap((chapter) => chapter.levels);

async function state(page: Page): Promise<AppState> {
  return page.evaluate(() => (document.querySelector('rt-app rt-lab') as unknown as { store: { state: AppState } }).store.state);
}

function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  return errors;
}

const task = (page: Page, title: string) => page.locator('rt-task-card').filter({ hasText: title });
const current = (page: Page) => page.locator('rt-task-card[status="current"]');
const panel = (page: Page) => page.locator('rt-quest-panel');

async function expectStatus(page: Page, title: string, status: string): Promise<void> {
  await expect(task(page, title)).toHaveAttribute('status', status);
}

async function distinctColours(locator: Locator): Promise<number> {
  const png = PNG.sync.read(await locator.screenshot());
  const colours = new Set<number>();
  for (let i = 0; i < png.data.length; i += 4) colours.add((png.data[i] << 16) | (png.data[i + 1] << 8) | png.data[i + 2]);
  return colours.size;
}

function overlaps(a: { x: number; y: number; width: number; height: number }, b: { x: number; y: number; width: number; height: number }): boolean {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

/** The ring is drawn around `target`: their boxes overlap and the ring is not far bigger. */
async function expectRingAround(page: Page, target: Locator): Promise<void> {
  const ring = page.getByTestId('guide-ring');
  await expect(ring).toBeVisible();
  await expect.poll(async () => {
    const [r, t] = [await ring.boundingBox(), await target.boundingBox()];
    return r !== null && t !== null && overlaps(r, t) && r.width < t.width + 60 && Math.abs(r.x + r.width / 2 - (t.x + t.width / 2)) < 12;
  }).toBe(true);
}

async function clickToolbar(page: Page, command: string): Promise<void> {
  await page.locator(`rt-view-toolbar [data-command="${command}"]`).click();
}

/** Drags the selected ball by the middle of its gizmo, in the view plane. */
async function dragBall(page: Page): Promise<void> {
  const at = await page.evaluate(() => {
    const view = document.querySelector('rt-app rt-lab')!.shadowRoot!.querySelector('rt-scene-view') as unknown as {
      labView: { projectToView(p: [number, number, number]): { x: number; y: number } | null };
      shadowRoot: ShadowRoot;
    };
    const lab = document.querySelector('rt-app rt-lab') as unknown as { store: { state: AppState } };
    const ball = lab.store.state.scene.objects.find((o) => o.id === 'ball')!;
    const point = view.labView.projectToView(ball.position as [number, number, number])!;
    const box = view.shadowRoot.querySelector('canvas')!.getBoundingClientRect();
    return { x: box.left + point.x, y: box.top + point.y };
  });
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  await page.mouse.move(at.x + 30, at.y + 10, { steps: 6 });
  await page.mouse.move(at.x + 60, at.y + 20, { steps: 6 });
  await page.mouse.up();
}

async function playLevel1(page: Page): Promise<void> {
  await expect(panel(page).getByRole('heading', { name: 'Introduction' })).toBeVisible();
  await expect(current(page)).toContainText('Look around');
  await clickToolbar(page, 'orbit-left');
  await expectStatus(page, 'Look around', 'done');

  // Hints: two texts, then the ring on the zoom buttons.
  await expect(current(page)).toContainText('Zoom in');
  await current(page).getByRole('button', { name: 'Hint' }).click();
  await expect(current(page)).toContainText('Scroll with the mouse wheel');
  await current(page).getByRole('button', { name: 'Another hint' }).click();
  await current(page).getByRole('button', { name: 'Show me where' }).click();
  await expectRingAround(page, page.locator('rt-view-toolbar .group').filter({ has: page.locator('[data-command="zoom-in"]') }));
  await clickToolbar(page, 'zoom-in');
  await expectStatus(page, 'Zoom in', 'done');
  await expect(page.getByTestId('guide-ring')).toHaveCount(0);

  // "Show me" once: the app selects the ball itself; the task counts as shown.
  await expect(current(page)).toContainText('Select the ball');
  await current(page).getByRole('button', { name: 'Hint' }).click();
  await current(page).getByRole('button', { name: 'Show me where' }).click();
  await expect(page.getByTestId('guide-ring')).toBeVisible();
  await current(page).getByRole('button', { name: 'Show me', exact: true }).click();
  await expectStatus(page, 'Select the ball', 'shown');
  expect((await state(page)).selection).toEqual({ kind: 'object', id: 'ball' });

  const hex = page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' });
  await hex.fill('#22cc44');
  await hex.press('Enter');
  await expectStatus(page, 'Paint the ball', 'done');

  await expect(current(page)).toContainText('Move the ball');
  await dragBall(page);
  await expectStatus(page, 'Move the ball', 'done');

  await page.locator('rt-scene-view canvas').focus();
  await page.keyboard.press('Escape');
  await expectStatus(page, 'Let go', 'done');

  await page.locator('[data-command="render-open"]').click();
  await expectStatus(page, 'Open the ray tracer', 'done');
  await expect(panel(page).getByText('Level complete!')).toBeVisible();
  await page.locator('rt-render-window').getByRole('button', { name: 'Close the render window' }).click();
}

async function playLevel2(page: Page): Promise<void> {
  await expect(panel(page).getByRole('heading', { name: 'Rays from the camera' })).toBeVisible();
  await current(page).getByRole('button', { name: 'Next' }).click();

  // Predict, then check.
  await current(page).getByRole('radio', { name: '12' }).check();
  await current(page).getByRole('button', { name: 'Check' }).click();
  await expect(task(page, 'Predict: how many rays?')).toContainText('Right!');

  await page.locator('rt-screen-preview [data-index="5"]').click();
  await expectStatus(page, 'One pixel', 'done');
  await page.locator('rt-screen-preview').getByRole('button', { name: 'Show all pixels' }).click();

  for (const [name, value] of [
    ['Pixel columns', '8'],
    ['Pixel rows', '6'],
  ]) {
    const field = page.locator('rt-tracer-panel').getByRole('textbox', { name: `${name}, typed value` });
    await field.fill(value);
    await field.press('Enter');
  }
  await page.locator('[data-command="render-open"]').click();
  await page.locator('rt-render-window button.primary').click();
  await expect(panel(page).getByText('Level complete!')).toBeVisible({ timeout: 60_000 });
  await page.locator('rt-render-window').getByRole('button', { name: 'Close the render window' }).click();
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

/** A progress file in which every level's mandatory tasks are done: every level is open on the map. */
function everythingPassed(): string {
  const levels: Record<string, { tasks: Record<string, { how: 'done'; points: number }>; hintsUsed: number }> = {};
  for (const id of levelIds) {
    const file = new URL(`${id}.level.json`, levelsFolder);
    if (!existsSync(file)) continue;
    try {
      const level = JSON.parse(readFileSync(file, 'utf8')) as { tasks: { id: string; mandatory?: boolean }[] };
      levels[id] = { tasks: Object.fromEntries(level.tasks.filter((t) => t.mandatory !== false).map((t) => [t.id, { how: 'done', points: 0 }])), hintsUsed: 0 };
    } catch {
      // A broken file is shown broken on the map; nothing to pass.
    }
  }
  const progress = {
    kind: 'ray-tracer-quest-progress',
    version: 1,
    levels,
    badges: [],
    settings: {},
    sandbox: null,
    current: null,
    log: { startedAt: new Date().toISOString(), events: [] },
  };
  return JSON.stringify(progress);
}

test('every level of levels/index.json loads from the map without errors, and its scene draws', async ({ page }) => {
  test.setTimeout(60_000 + levelIds.length * 15_000);
  expect(readdirSync(levelsFolder).length).toBeGreaterThan(1);
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  // Import a file that opens every level, as a learner continuing on another computer would.
  await page.getByRole('button', { name: 'Menu' }).click();
  await page.locator('rt-progress-menu input[type=file]').setInputFiles({ name: 'progress.json', mimeType: 'application/json', buffer: Buffer.from(everythingPassed()) });
  await expect(page.locator('rt-toast')).toContainText('Progress imported');
  await page.keyboard.press('Escape');
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
  await expect(page.locator('rt-toast')).toContainText('kept as a backup');
  await expect(panel(page).getByRole('heading', { name: 'Introduction' })).toBeVisible();
  const keys = await page.evaluate(() => Object.keys(localStorage));
  expect(keys.some((key) => key.startsWith('rtq.progress.backup.'))).toBe(true);
});
