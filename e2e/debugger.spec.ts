import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, readFileSync } from 'node:fs';
import { debugProgram, raysShownAt, type DebugProgram } from '../src/debugger/debug-steps.ts';
import { DEFAULT_SEED } from '../src/render/render-job.ts';
import { defaultScene } from '../src/scene/scene-defaults.ts';
import type { PixelTrace, RayNode } from '../src/tracer/ray-tree.ts';
import { tracePixel } from '../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../src/tracer/tracer-scene.ts';
import { collectErrors, importProgress, levelsFolder, panel, progressFile } from './support/game-steps.ts';

/**
 * The ray debugger as a student uses it: choose a pixel of the camera's image, open the
 * debugger and step with the keyboard to the end, through a mirror pixel and a glass pixel
 * of the free lab's scene. At every step the screen is checked against the same steps
 * computed here from the tracer: the highlighted ray's kind, the lit line of the
 * pseudocode, the number of rays drawn in 3D, the equation's terms adding up to its sum,
 * and at the end the pixel's colour equal to the image's pixel.
 *
 * It relies on: <rt-screen-preview>'s pixel buttons ("Pixel x, y"), <rt-ray-debugger>'s
 * buttons and its data-step / data-line / data-ray, the pseudocode's aria-current line,
 * and the 3D view's element carrying `data-ray-instances`.
 */

const SHOTS = process.env.E2E_SHOTS ?? 'test-results/debugger';

const scene = defaultScene();
const tracer = buildTracerScene(scene, new Map());
const [columns, rows] = scene.camera.pixels;
const traces: PixelTrace[] = Array.from({ length: columns * rows }, (_, p) => tracePixel(tracer, p % columns, Math.floor(p / columns), DEFAULT_SEED, { terms: true }));

function rays(nodes: RayNode[]): RayNode[] {
  return nodes.flatMap((node) => [node, ...rays(node.children)]);
}

/** The pixel whose first ray hits `objectId` with the most rays below it (the most to step through). */
function pixelOn(objectId: string): PixelTrace {
  const on = traces.filter((trace) => trace.rays[0].objectId === objectId);
  return on.sort((a, b) => rays(b.rays).length - rays(a.rays).length)[0];
}

/** Numbers in a text, in order ("(0.125, 0.500, 1.000)" → [0.125, 0.5, 1]). */
function numbers(text: string): number[] {
  return [...text.matchAll(/-?\d+\.\d+/g)].map((match) => Number(match[0]));
}

async function checkEquation(page: Page): Promise<void> {
  const equation = page.locator('rt-debug-equation');
  const values = await equation.locator('.value').allTextContents();
  if (values.length < 2) return;
  const sumRow = await equation.locator('.total .value').first().textContent();
  const terms = values.slice(0, values.length - (await equation.locator('.total').count()));
  const sum = numbers(sumRow ?? '');
  for (let c = 0; c < 3; c++) {
    const added = terms.reduce((total, text) => total + numbers(text)[c], 0);
    // Each shown value is rounded to 3 decimals.
    expect(Math.abs(added - sum[c])).toBeLessThanOrEqual(0.0005 * (terms.length + 1));
  }
}

async function stepThrough(page: Page, name: string, trace: PixelTrace): Promise<void> {
  const [x, y] = trace.pixel;
  const program: DebugProgram = debugProgram(trace, scene);
  await page.locator('rt-screen-preview').getByRole('button', { name: `Pixel ${x}, ${y}`, exact: true }).click();
  await page.getByRole('button', { name: 'Debug a pixel' }).click();
  const debuggerPanel = page.locator('rt-ray-debugger');
  const view = page.locator('[data-ray-instances]').first();
  for (let index = 0; index < program.steps.length; index++) {
    const step = program.steps[index];
    await expect(debuggerPanel).toHaveAttribute('data-step', String(index));
    await expect(debuggerPanel).toHaveAttribute('data-ray', step.ray?.type ?? '');
    await expect(debuggerPanel.locator('rt-debug-code [aria-current="step"]')).toHaveAttribute('data-line', step.line);
    // Each ray drawn, and the normal at each hit it reaches (drawn for the debugger's pixel).
    const shown = raysShownAt(program, index);
    const cylinders = shown.filter((ray) => !ray.corners).length + shown.filter((ray) => ray.normal !== undefined).length;
    await expect(view).toHaveAttribute('data-ray-instances', String(cylinders));
    await checkEquation(page);
    // At the first hit, its reflection's term highlights that ray (drawn even before it is cast).
    const reflect = step.kind === 'shade' && step.depth === 0 ? step.ray?.children.find((child) => child.type === 'reflect') : undefined;
    if (reflect) {
      const term = debuggerPanel.locator('rt-debug-equation').getByRole('button', { name: /Reflected ray/ });
      await term.click();
      await expect(term).toHaveAttribute('aria-pressed', 'true');
      await expect(debuggerPanel).toHaveAttribute('data-ray', 'reflect');
      await expect(view).toHaveAttribute('data-ray-instances', String(cylinders + 1));
      await page.screenshot({ path: `${SHOTS}/${name}-${String(index).padStart(2, '0')}-term-clicked.png` });
    }
    if (index === 0 || step.kind === 'split' || step.kind === 'average') {
      await page.screenshot({ path: `${SHOTS}/${name}-${String(index).padStart(2, '0')}-${step.kind}.png` });
    }
    if (index < program.steps.length - 1) await page.keyboard.press('ArrowRight');
  }
  // The last step: the pixel, as the mean of its samples, equals the image's pixel.
  const totals = await page.locator('rt-debug-equation .total .value').allTextContents();
  expect(totals).toHaveLength(2);
  expect(totals[0]).toBe(totals[1]);
  expect(numbers(totals[0])).toEqual(trace.color.map((value) => Number(value.toFixed(3))));
  await page.getByRole('button', { name: 'Close', exact: true }).click();
  await expect(page.getByRole('button', { name: 'Debug a pixel' })).toBeVisible();
}

test('step through a mirror pixel and a glass pixel to the end', async ({ page }) => {
  mkdirSync(SHOTS, { recursive: true });
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  await page.goto('./#free-lab');
  await expect(page.locator('rt-screen-preview').getByRole('button', { name: 'Pixel 0, 0', exact: true })).toBeVisible();

  const mirror = pixelOn('mirror-ball');
  const glass = pixelOn('glass-ball');
  expect(rays(mirror.rays).some((ray) => ray.type === 'reflect')).toBe(true);
  expect(rays(glass.rays).some((ray) => ray.type === 'refract')).toBe(true);
  await stepThrough(page, 'mirror', mirror);
  await stepThrough(page, 'glass', glass);
  expect(errors).toEqual([]);
});

test('a level\'s debugger task: the ring shows the way in, and "Show me" steps to the blocked shadow ray', async ({ page }) => {
  mkdirSync(SHOTS, { recursive: true });
  const errors = collectErrors(page);
  const index = JSON.parse(readFileSync(new URL('index.json', levelsFolder), 'utf8')) as { chapters: { levels: string[] }[] };
  const levelIds = index.chapters.flatMap((chapter) => chapter.levels);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await importProgress(page, progressFile(levelIds.slice(0, levelIds.indexOf('04-shadows'))));
  if (!(await page.locator('rt-level-map').isVisible())) await page.locator('[data-command="levels"]').click();
  await page.locator('rt-level-map [data-level="04-shadows"]').click();
  await expect(panel(page).locator('h2')).toBeVisible();

  const card = page.locator('rt-task-card[data-task="debug-shadow"]');
  await card.getByRole('button', { name: /What blocks the light\?/ }).click();
  const ladder = card.locator('rt-hint-box button[data-hint]');
  for (let rung = 0; rung < 6; rung++) {
    const kind = await ladder.getAttribute('data-hint');
    await ladder.click();
    if (kind === 'guidance') {
      // The ring is around the debugger's button (it stands for the Step button while closed).
      const button = (await page.getByRole('button', { name: 'Debug a pixel' }).boundingBox())!;
      const ring = (await page.getByTestId('guide-ring').boundingBox())!;
      expect(Math.abs(ring.x + ring.width / 2 - (button.x + button.width / 2))).toBeLessThan(12);
    }
    if (kind === 'show-me') break;
  }
  const debuggerPanel = page.locator('rt-ray-debugger');
  await expect(debuggerPanel).toHaveAttribute('data-ray', 'shadow');
  await expect(debuggerPanel.locator('rt-debug-code [aria-current="step"]')).toHaveAttribute('data-line', 'blocked');
  await expect(debuggerPanel.getByText(/In shadow: Ball is between the point and Lamp/)).toBeVisible();
  await expect(card).toHaveAttribute('status', 'shown');
  await page.screenshot({ path: `${SHOTS}/level-04-show-me.png` });
  expect(errors).toEqual([]);
});
