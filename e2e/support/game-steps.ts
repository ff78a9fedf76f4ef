import { expect, type Locator, type Page } from '@playwright/test';
import { existsSync, readFileSync } from 'node:fs';
import type { LabState } from '../../src/lab-state/lab-state.ts';

// Steps of the game as a student plays it: through the buttons, fields and keys of the page.
// The store and the view are only read (state, where the ball is on screen), never driven.
// Shared by the game's and the classroom's specs.

/** The lab's current app state (read only). */
export async function state(page: Page): Promise<LabState> {
  return page.evaluate(() => (document.querySelector('rt-app rt-lab') as unknown as { store: { state: LabState } }).store.state);
}

/** Console errors and uncaught exceptions of the page, collected from now on. */
export function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  return errors;
}

/** The levels' folder, read by the specs as the app's own files. */
export const levelsFolder = new URL('../../levels/', import.meta.url);

export const task = (page: Page, title: string) => page.locator('rt-task-card').filter({ hasText: title });
export const current = (page: Page) => page.locator('rt-task-card[status="current"]');
export const panel = (page: Page) => page.locator('rt-quest-panel');

/**
 * Waits until the 3D view's code has loaded: until then the page says "Loading the 3D view…"
 * and keys pressed on the canvas reach nothing (a slow machine can take seconds).
 */
export async function viewLoaded(page: Page): Promise<void> {
  await expect(page.getByText('Loading the 3D view…')).toHaveCount(0);
}

export async function expectStatus(page: Page, title: string, status: string): Promise<void> {
  await expect(task(page, title)).toHaveAttribute('status', status);
}

function overlaps(a: { x: number; y: number; width: number; height: number }, b: { x: number; y: number; width: number; height: number }): boolean {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

/** The ring is drawn around `target`: their boxes overlap and the ring is not far bigger. */
export async function expectRingAround(page: Page, target: Locator): Promise<void> {
  const ring = page.getByTestId('guide-ring');
  await expect(ring).toBeVisible();
  await expect
    .poll(async () => {
      const [r, t] = [await ring.boundingBox(), await target.boundingBox()];
      return r !== null && t !== null && overlaps(r, t) && r.width < t.width + 60 && Math.abs(r.x + r.width / 2 - (t.x + t.width / 2)) < 12;
    })
    .toBe(true);
}

export async function clickToolbar(page: Page, command: string): Promise<void> {
  await page.locator(`rt-view-toolbar [data-command="${command}"]`).click();
}

/** Drags the selected ball by the middle of its gizmo, in the view plane. */
/** Where the object `id` (its centre) is on the page, in viewport px, as the 3D view projects it. */
export async function objectOnScreen(page: Page, id: string): Promise<{ x: number; y: number }> {
  return page.evaluate((objectId) => {
    const view = document.querySelector('rt-app rt-lab')!.shadowRoot!.querySelector('rt-scene-view') as unknown as {
      labView: { projectToView(p: readonly number[]): { x: number; y: number } | null };
      shadowRoot: ShadowRoot;
    };
    const lab = document.querySelector('rt-app rt-lab') as unknown as { store: { state: LabState } };
    const point = view.labView.projectToView(lab.store.state.scene.objects.find((o) => o.id === objectId)!.position)!;
    const box = view.shadowRoot.querySelector('canvas')!.getBoundingClientRect();
    return { x: box.left + point.x, y: box.top + point.y };
  }, id);
}

async function dragBall(page: Page): Promise<void> {
  const at = await objectOnScreen(page, 'ball');
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  await page.mouse.move(at.x + 30, at.y + 10, { steps: 6 });
  await page.mouse.move(at.x + 60, at.y + 20, { steps: 6 });
  await page.mouse.up();
}

/**
 * Level 1's tasks up to its last one, "Open the ray tracer", which the caller does
 * (`renderFirstImage`) and checks: what follows differs in free play (the level's end) and
 * in an assignment (its survey). Uses two text hints, a "Show me where" and one "Show me".
 */
export async function playLevel1UpToTheRayTracer(page: Page): Promise<void> {
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
  await expect(current(page)).toContainText('Open the ray tracer');
}

/** Opens the render window with the header's button. */
export async function openRayTracer(page: Page): Promise<void> {
  await page.locator('[data-command="render-open"]').click();
}

/** Level 1's last task: open the render window and render the image (opening alone shows no image yet). */
export async function renderFirstImage(page: Page): Promise<void> {
  await openRayTracer(page);
  await page.locator('rt-render-window button.primary').click();
  await expect(page.locator('rt-render-window [data-testid="render-status"]')).toContainText('Done in', { timeout: 60_000 });
}

export async function closeRenderWindow(page: Page): Promise<void> {
  await page.locator('rt-render-window').getByRole('button', { name: 'Close the render window' }).click();
}

/** A progress file in which the mandatory tasks of `passed` are done: those levels and the next are open on the map. */
export function progressFile(passed: readonly string[]): string {
  const levels: Record<string, { tasks: Record<string, { how: 'done'; points: number }>; hintsUsed: number }> = {};
  for (const id of passed) {
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

/** Imports `file` through the progress menu, as a learner continuing on another computer would. */
export async function importProgress(page: Page, file: string): Promise<void> {
  await page.getByRole('button', { name: 'Menu' }).click();
  await page.locator('rt-progress-menu input[type=file]').setInputFiles({ name: 'progress.json', mimeType: 'application/json', buffer: Buffer.from(file) });
  await expect(page.locator('rt-toast')).toContainText('Progress imported');
  await page.keyboard.press('Escape');
}

/** Picks a prediction's choice by its words (or a picture's "picture B") and locks it in. */
export async function lockIn(page: Page, choice: string): Promise<void> {
  const id = await current(page).getAttribute('data-task');
  const card = page.locator(`rt-task-card[data-task="${id}"]`);
  await card.getByRole('radio', { name: choice, exact: true }).check();
  await card.getByRole('button', { name: 'Lock in my prediction' }).click();
  // Locked in, and not judged yet: the result is for the next task to show.
  await expect(card).not.toHaveAttribute('status', 'current');
  await expect(card).not.toContainText('the answer is');
}

/** Types a number prediction and locks it in. */
export async function lockInNumber(page: Page, value: string): Promise<void> {
  const card = current(page);
  await card.getByRole('textbox', { name: 'Your number' }).fill(value);
  await card.getByRole('button', { name: 'Lock in my prediction' }).click();
}

/**
 * The prediction `title`, revealed once its observation is done: when the learner expected
 * something else, says `seen` is what they see; then `read` looks at the answer and why
 * (the card folds once the learner continues).
 */
export async function continueFromPrediction(page: Page, title: string, seen?: string, read?: (card: Locator) => Promise<void>): Promise<void> {
  const card = task(page, title);
  const quiz = card.locator('rt-quiz');
  if (seen !== undefined) {
    await expect(quiz).toContainText('What do you see?');
    await quiz.getByRole('radio', { name: seen, exact: true }).check();
    await quiz.getByRole('button', { name: 'This is what I see' }).click();
  }
  await read?.(card);
  await quiz.getByRole('button', { name: 'Continue' }).click();
  await expect(quiz.getByRole('button', { name: 'Continue' })).toHaveCount(0);
}
