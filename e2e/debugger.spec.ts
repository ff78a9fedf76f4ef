import { issueLine } from '../src/util/issue.ts';
import { expect, test, type Page } from '@playwright/test';
import { mkdirSync, readFileSync } from 'node:fs';
import { encodeSceneLink } from '../src/app/scene-link.ts';
import { debugProgram, raysShownAt, type DebugProgram } from '../src/debugger/debug-steps.ts';
import { parseLevel } from '../src/quest/level-schema.ts';
import { DEFAULT_SEED } from '../src/render/render-job.ts';
import { defaultScene } from '../src/scene/scene-defaults.ts';
import type { Scene } from '../src/scene/scene.ts';
import { pixelBytes } from '../src/tracer/quantize.ts';
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
 * Then a lens, a glossy and an area-light pixel (issue 37), opened from a scene link of their
 * level's scene: the rows of the pixel's tree nest on screen, the running sum under them is
 * the tracer's at every step and ends at the pixel the screen preview shows (8-bit), and at
 * 1366×768 every term of the equation can be scrolled to while its sum stays put.
 *
 * It relies on: <rt-screen-preview>'s pixel buttons ("Pixel x, y"), <rt-ray-debugger>'s
 * buttons and its data-step / data-line / data-ray, the pseudocode's aria-current line,
 * <rt-debug-tree>'s rows (data-level, aria-current) and `.running` sum, the equation's
 * `ul.terms` and `ul.sums`, and the 3D view's element carrying `data-ray-instances`.
 */

const SHOTS = process.env.E2E_SHOTS ?? 'test-results/debugger';

const scene = defaultScene();
const tracer = buildTracerScene(scene, new Map());
const [columns, rows] = scene.camera.pixels;
const traces: PixelTrace[] = Array.from({ length: columns * rows }, (_, p) =>
  tracePixel(tracer, p % columns, Math.floor(p / columns), DEFAULT_SEED, { terms: true }),
);

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
  await page
    .locator('rt-screen-preview')
    .getByRole('button', { name: `Pixel ${x}, ${y}`, exact: true })
    .click();
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

/** A level's starting scene with `change` made, as a learner makes it in that level. */
function levelScene(id: string, change: (scene: Scene) => void): Scene {
  const parsed = parseLevel(JSON.parse(readFileSync(new URL(`${id}.level.json`, levelsFolder), 'utf8')));
  if (!parsed.ok) throw new Error(parsed.errors.map(issueLine).join('\n'));
  const scene = structuredClone(parsed.level.scene);
  change(scene);
  return scene;
}

/** Every pixel of the scene's screen, traced with terms, as the debugger traces it. */
function screenOf(scene: Scene): PixelTrace[] {
  const traced = buildTracerScene(scene, new Map());
  const [width, height] = scene.camera.pixels;
  return Array.from({ length: width * height }, (_, p) => tracePixel(traced, p % width, Math.floor(p / width), DEFAULT_SEED, { terms: true }));
}

/** Numbers of a text in either language's format ("(0,125; 0,500)" or "(0.125, 0.500)"). */
const valuesOf = (text: string | null) => [...(text ?? '').matchAll(/-?\d+[.,]\d+/g)].map((match) => Number(match[0].replace(',', '.')));

/** Each case: its scene, how its pixel is picked, and how deep its tree nests at least (pixel sample → ray → hit → its rays). */
const distributed: { name: string; scene: Scene; pick: (trace: PixelTrace) => boolean; nests: number }[] = [
  {
    // Depth of field: aperture 0.165 with 2 × 2 lens points, the case the debugger once called "its one sample".
    name: 'lens',
    scene: levelScene('18-depth-of-field', (scene) => Object.assign(scene.camera, { aperture: 0.165, lensSamples: 2 })),
    pick: (trace) => trace.rays[0].children.filter((child) => child.lensPoint).length === 4 && rays(trace.rays).some((ray) => ray.objectId === 'near-ball'),
    nests: 2,
  },
  {
    // A rough metal floor: a fan of 3 × 3 glossy rays, some reaching the ball or the board.
    name: 'glossy',
    scene: levelScene('19-glossy-reflections', (scene) => Object.assign(scene.objects.find((object) => object.id === 'floor')!.material, { roughness: 0.3 })),
    pick: (trace) => rays(trace.rays).filter((ray) => ray.glossy && ray.hit && ray.objectId !== null && ray.objectId !== 'floor').length >= 3,
    nests: 2,
  },
  {
    // Supersampling 3 (level 11's solution): nine sample rows, each ray under its sample, an edge pixel whose samples differ.
    name: 'supersampled',
    scene: levelScene('11-anti-aliasing', (scene) => Object.assign(scene.settings, { supersampling: 3 })),
    pick: (trace) => trace.rays.length === 9 && new Set(trace.rays.map((ray) => ray.objectId)).size > 1,
    nests: 1,
  },
  {
    // An area light with 3 × 3 samples over a point at the edge of the pole's shadow: some samples blocked, some not.
    name: 'area-light',
    scene: levelScene('10-area-lights', (scene) =>
      Object.assign(
        scene.lights.find((light) => light.id === 'panel')!,
        { samples: 3 },
      ),
    ),
    pick: (trace) => {
      const samples = trace.rays[0].children.filter((child) => child.lightId === 'panel');
      return samples.length === 9 && samples.some((ray) => ray.type === 'shadow') && samples.some((ray) => ray.type === 'light');
    },
    nests: 1,
  },
];

for (const { name, scene, pick, nests } of distributed) {
  test(`${name === 'area-light' ? 'an' : 'a'} ${name} pixel: its rays as a tree, a sum that grows to the image's pixel, terms that scroll at 1366×768`, async ({
    page,
  }) => {
    mkdirSync(SHOTS, { recursive: true });
    const errors = collectErrors(page);
    const trace = screenOf(scene).find(pick);
    if (!trace) throw new Error(`no ${name} pixel on the screen`);
    const program = debugProgram(trace, scene);
    const [x, y] = trace.pixel;
    await page.goto(`./${await encodeSceneLink(scene)}`);
    // The linked scene's screen, not the lab's first one.
    const [width, height] = scene.camera.pixels;
    await expect(page.locator('rt-screen-preview').getByRole('group', { name: `Camera image, ${width} × ${height} pixels` })).toBeVisible();
    const cell = page.locator('rt-screen-preview').getByRole('button', { name: `Pixel ${x}, ${y}`, exact: true });
    await cell.click();
    await expect(cell).toHaveAttribute('aria-pressed', 'true');
    const shown = await cell.evaluate((element) => getComputedStyle(element).backgroundColor);
    await page.getByRole('button', { name: 'Debug a pixel' }).click();
    const debuggerPanel = page.locator('rt-ray-debugger');
    await expect(debuggerPanel.locator('.where')).toContainText(`Pixel ${x}, ${y}`);
    const tree = debuggerPanel.locator('rt-debug-tree');
    const sum = tree.locator('.running');
    const steps = program.steps;
    let grew = 0;
    for (let index = 0; index < steps.length; index++) {
      await expect(debuggerPanel).toHaveAttribute('data-step', String(index));
      // The running sum is the steps' so far (shown to 3 decimals), and stays in view.
      expect(valuesOf(await sum.locator('.value').textContent())).toEqual(steps[index].sum.map((value) => Number(value.toFixed(3))));
      if (index > 0 && steps[index].sum.some((value, c) => value > steps[index - 1].sum[c])) grew++;
      await expect(tree.locator('li[aria-current="step"]')).toHaveAttribute('data-level', String(steps[index].level));
      const equation = debuggerPanel.locator('rt-debug-equation');
      if (steps[index].kind === 'shade' || index === steps.length - 1) await checkScrolls(page, equation);
      if (index === steps.length - 1) await checkTreeScrolls(page, tree);
      if (
        steps[index].kind === 'shade' &&
        steps[index].level === nests &&
        !steps.slice(0, index).some((step) => step.kind === 'shade' && step.level === nests)
      ) {
        await page.screenshot({ path: `${SHOTS}/${name}-nested.png` });
      }
      if (index < steps.length - 1) await page.keyboard.press('ArrowRight');
    }
    expect(grew).toBeGreaterThan(2);
    // Nested on screen: a deeper row starts further right than a shallower one.
    const levels = await tree
      .locator('li[data-level]')
      .evaluateAll((rows) =>
        rows.map((row) => ({ level: Number(row.getAttribute('data-level')), left: row.querySelector('.label')!.getBoundingClientRect().left })),
      );
    const deepest = Math.max(...levels.map((row) => row.level));
    expect(deepest).toBeGreaterThanOrEqual(nests);
    const leftOf = (level: number) => levels.find((row) => row.level === level)!.left;
    for (let level = 1; level <= deepest; level++) expect(leftOf(level)).toBeGreaterThan(leftOf(level - 1) + 8);
    // The end: the sum is the image's pixel, as the screen preview shows it, in 8 bits.
    const bytes = pixelBytes(steps.at(-1)!.sum, x, y, scene.settings);
    await expect(sum.locator('.note')).toContainText(`8-bit: ${bytes.join(', ')}`);
    expect(shown).toBe(`rgb(${bytes.join(', ')})`);
    const totals = await debuggerPanel.locator('rt-debug-equation .total').allTextContents();
    expect(totals.map((text) => text.replace(/\s+/g, ' '))).toEqual([
      expect.stringContaining(`8-bit: ${bytes.join(', ')}`),
      expect.stringContaining(`8-bit: ${bytes.join(', ')}`),
    ]);
    await page.screenshot({ path: `${SHOTS}/${name}-end.png` });
    expect(errors).toEqual([]);
  });
}

/** The equation's rows all reachable at 1366×768: its list scrolls inside the debugger, its sum stays on screen. */
async function checkScrolls(page: Page, equation: ReturnType<Page['locator']>): Promise<void> {
  const list = equation.locator('ul.terms');
  const sums = equation.locator('ul.sums');
  const card = (await page.locator('rt-ray-debugger .card').boundingBox())!;
  const listBox = (await list.boundingBox())!;
  const sumsBox = (await sums.boundingBox())!;
  expect(listBox.y + listBox.height).toBeLessThanOrEqual(card.y + card.height);
  expect(sumsBox.y + sumsBox.height).toBeLessThanOrEqual(Math.min(card.y + card.height, 768));
  const rows = list.locator(':scope > li');
  for (let i = 0; i < (await rows.count()); i++) {
    await rows.nth(i).evaluate((row) => row.scrollIntoView({ block: 'nearest' }));
    const box = (await rows.nth(i).boundingBox())!;
    const now = (await list.boundingBox())!;
    expect(box.y).toBeGreaterThanOrEqual(now.y - 1);
    expect(box.y + box.height).toBeLessThanOrEqual(now.y + now.height + 1);
  }
  // Scrolling the terms does not move the sum.
  expect((await sums.boundingBox())!.y).toBeCloseTo(sumsBox.y, 0);
}

/** Every row of the pixel's tree reachable at 1366×768: its list scrolls inside the dock, the running sum under it stays on screen and in place. */
async function checkTreeScrolls(page: Page, tree: ReturnType<Page['locator']>): Promise<void> {
  const list = tree.locator('ol');
  const sum = tree.locator('.running');
  const card = (await page.locator('rt-ray-debugger .card').boundingBox())!;
  const sumAt = (await sum.boundingBox())!;
  const listAt = (await list.boundingBox())!;
  expect(listAt.y + listAt.height).toBeLessThanOrEqual(sumAt.y + 1);
  expect(sumAt.y + sumAt.height).toBeLessThanOrEqual(Math.min(card.y + card.height, 768));
  // More rows than fit: the list scrolls (a pixel of several samples has dozens of steps).
  expect(await list.evaluate((element) => element.scrollHeight > element.clientHeight)).toBe(true);
  const rows = list.locator(':scope > li');
  const count = await rows.count();
  for (const i of [0, Math.floor(count / 2), count - 1]) {
    await rows.nth(i).evaluate((row) => row.scrollIntoView({ block: 'nearest' }));
    const box = (await rows.nth(i).boundingBox())!;
    const now = (await list.boundingBox())!;
    expect(box.y).toBeGreaterThanOrEqual(now.y - 1);
    expect(box.y + box.height).toBeLessThanOrEqual(now.y + now.height + 1);
    expect((await sum.boundingBox())!.y).toBeCloseTo(sumAt.y, 0);
  }
}
