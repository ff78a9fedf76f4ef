import { expect, test, type Page } from '@playwright/test';
import { allPassedBut, CORRECT_HIT_SPHERE as CORRECT, openCodeTask, shownCase, typeCode } from './support/code-lab-steps.ts';
import { collectErrors, expectStatus, progressFile } from './support/game-steps.ts';

// The first code lab (issue 43): a correct hitSphere passes every case and completes the task;
// the learner's code cannot reach the page, the stored progress or the network; an endless
// loop is stopped after 2 s with a message while the page stays responsive, and the next Run works.

const LEVEL = '02-rays-from-the-camera';
const TITLE = 'Code lab: where does a ray hit the ball?';

// Every door it tries must be shut; the exception (line 10) lists any that opened.
const PROBE = `function hitSphere() {
  const opened = [];
  const tryIt = (name, open) => { try { open(); opened.push(name); } catch {} };
  tryIt('localStorage', () => localStorage.getItem('rtq.progress'));
  tryIt('document', () => document.title.length);
  tryIt('indexedDB', () => indexedDB.open('x'));
  tryIt('fetch', () => { const request = new XMLHttpRequest(); request.open('GET', '/', false); request.send(); });
  tryIt('postMessage', () => postMessage({ type: 'done', outcomes: [] }));
  tryIt('parent', () => parent.document);
  throw new Error('opened [' + opened.join(', ') + ']');
}`;

// "t < 0 accepted": the near root, wherever it lies.
const BEHIND = `function hitSphere(origin, direction, center, radius) {
  const oc = sub(origin, center);
  const b = dot(oc, direction);
  const d = b * b - (dot(oc, oc) - radius * radius);
  return d < 0 ? null : -b - Math.sqrt(d);
}`;

const ENDLESS = `function hitSphere() {
  while (true) {}
}`;

// Lambert without the clamp: a light behind the surface gives a negative colour.
const PHONG_NOT_CLAMPED = `function shade(point, normal, toEye, light, material) {
  const L = normalize(sub(light.position, point));
  const nDotL = dot(normal, L);
  const R = sub(scale(normal, 2 * nDotL), L);
  const highlight = material.specular * Math.pow(Math.max(dot(R, toEye), 0), material.shininess);
  const channel = (lc, c) => light.intensity * lc * (material.diffuse * nDotL * c + highlight);
  return { r: channel(light.color.r, material.color.r), g: channel(light.color.g, material.color.g), b: channel(light.color.b, material.color.b) };
}`;

// Uniform over the pixel, not stratified: some cells get two points, others none.
const NOT_STRATIFIED = `function pixelSamples(n, random) {
  const points = [];
  for (let k = 0; k < n; k++) points.push({ x: random(), y: random() });
  return points;
}`;

type DrawnCase = { segments: { label?: string; mark: string }[]; points: { mark: string }[]; shapes: { kind: string; fill?: string }[] } | null;
/** The case the view shows (its declared `labCase.shown`), once the view has glided to it and drawn its last frame; and how many CSS pixels the case covers on the canvas then. */
async function drawnCase(page: Page): Promise<{ shown: DrawnCase; covered: number }> {
  type Probed = { labView: { labCase: { shown: DrawnCase }; probes: { idle: boolean; caseCoverage(): { mask: Uint8Array } } } };
  await expect
    .poll(() => page.locator('rt-scene-view').evaluate((element) => (element as unknown as Probed).labView.probes.idle), { timeout: 30_000 })
    .toBe(true);
  return page.locator('rt-scene-view').evaluate((element) => {
    const view = (element as unknown as Probed).labView;
    return { shown: view.labCase.shown, covered: view.probes.caseCoverage().mask.reduce((sum, covered) => sum + covered, 0) };
  });
}

/** How many CSS pixels of the canvas the scene's own rays cover, once the view has drawn its last frame. */
async function raysCovered(page: Page): Promise<number> {
  type Probed = { labView: { probes: { idle: boolean; rayCoverage(): { mask: Uint8Array } } } };
  const view = page.locator('rt-scene-view');
  await expect.poll(() => view.evaluate((element) => (element as unknown as Probed).labView.probes.idle), { timeout: 30_000 }).toBe(true);
  return view.evaluate((element) => (element as unknown as Probed).labView.probes.rayCoverage().mask.reduce((sum, covered) => sum + covered, 0));
}

test('a code lab grades a correct function, and hostile code reaches nothing and is stopped', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, progressFile(['01-introduction']), LEVEL, 'code-hit-sphere');
  const run = lab.getByRole('button', { name: 'Run tests' });
  const result = lab.getByRole('status');
  await expect(lab.getByRole('textbox', { name: 'Your function: code editor' })).toBeVisible();

  await typeCode(page, PROBE);
  await run.click();
  await expect(result).toContainText('Your function threw Error: opened [] at line 10.');
  expect(await page.evaluate(() => localStorage.getItem('rtq.progress'))).toContain('01-introduction');

  await typeCode(page, ENDLESS);
  const started = Date.now();
  await run.click();
  // The page answers while the loop runs.
  expect(await page.evaluate(() => document.title.length)).toBeGreaterThan(0);
  expect(Date.now() - started).toBeLessThan(1500);
  await expect(result).toContainText('Your function did not return within 2 s on case 1. Is there a loop that never ends?');

  // The first failing case is drawn in the 3D view: its sphere, the tracer's hit and the learner's.
  await typeCode(page, BEHIND);
  await run.click();
  await expect(result).toContainText('First failing case: case 3, a sphere behind the ray’s origin.');
  expect(await shownCase(page)).toMatchObject({ points: [{ mark: 'got' }], shapes: [{ kind: 'sphere' }] });
  // The scene's own rays stand aside while the case is drawn, so that its few rays read on their own.
  expect(await raysCovered(page), 'CSS pixels the scene’s rays cover beside the case').toBe(0);
  await page.screenshot({ path: 'test-results/screens/code-lab-case-without-rays.png' });

  await typeCode(page, CORRECT);
  await run.click();
  await expect(result).toContainText('306 of 306 cases pass.');
  expect(await shownCase(page)).toBeNull();
  expect(await raysCovered(page), 'CSS pixels the scene’s rays cover once the case is gone').toBeGreaterThan(500);
  await expectStatus(page, TITLE, 'done');
  // The code is kept for the next visit.
  expect(await page.evaluate(() => localStorage.getItem('rtq.code-lab.ray-sphere'))).toContain('const oc = sub(origin, center);');
  expect(errors).toEqual([]);
});

test('a Phong function whose cos is not clamped fails on the light behind the surface, drawn with N, L, V and R', async ({ page }) => {
  const errors = collectErrors(page);
  await openCodeTask(page, allPassedBut('03-shading'), '03-shading', 'code-shade');
  const lab = page.locator('rt-code-lab');
  await typeCode(page, PHONG_NOT_CLAMPED);
  await lab.getByRole('button', { name: 'Run tests' }).click();
  const result = lab.getByRole('status');
  await expect(result).toContainText('First failing case: case 1, a light behind the surface.');
  await expect(result).toContainText('the light is behind the surface here, L points below it (N·L < 0), so it adds nothing');
  await expect(result).toContainText('Drawn in the 3D view: the point on a piece of its surface, with N: the normal;');
  await expect(result).toContainText('Expected: (0, 0, 0); got: (-0.849');
  const { shown, covered } = await drawnCase(page);
  expect(shown?.segments.map((segment) => segment.label)).toEqual(['N', 'L', 'V', 'R']);
  expect(shown?.points.map((point) => point.mark)).toEqual(['surface', 'light']);
  expect(covered, 'CSS pixels the case covers on the canvas').toBeGreaterThan(500);
  expect(errors).toEqual([]);
});

test('samples that are not stratified fail on a run, drawn as the pixel with its cells and the run’s points', async ({ page }) => {
  const errors = collectErrors(page);
  await openCodeTask(page, allPassedBut('11-anti-aliasing'), '11-anti-aliasing', 'code-jittered-samples');
  const lab = page.locator('rt-code-lab');
  await typeCode(page, NOT_STRATIFIED);
  await lab.getByRole('button', { name: 'Run tests' }).click();
  const result = lab.getByRole('status');
  await expect(result).toContainText('so another cell has none. Each cell gets exactly one point.');
  await expect(result).toContainText('Drawn in the 3D view: the pixel with its grid of cells and this run’s points;');
  const { shown, covered } = await drawnCase(page);
  const fills = shown?.shapes.map((shape) => shape.fill) ?? [];
  expect(fills[0]).toBe('pixel');
  expect(fills).toContain('crowded');
  expect(fills).toContain('empty');
  expect(shown?.points.every((point) => point.mark === 'sample')).toBe(true);
  expect(covered, 'CSS pixels the pixel and its points cover on the canvas').toBeGreaterThan(5000);
  expect(errors).toEqual([]);
});

// Memory without end: arrays of a million numbers each, kept, until the time limit or the worker's heap ends it.
const HOARDER = `function hitSphere() {
  const kept = [];
  while (true) kept.push(new Array(1e6).fill(kept.length));
}`;

test('code that allocates without end is stopped, the page answering and the stored progress kept', async ({ page }) => {
  const errors = collectErrors(page);
  const lab = await openCodeTask(page, progressFile(['01-introduction']), LEVEL, 'code-hit-sphere');
  const run = lab.getByRole('button', { name: 'Run tests' });
  const result = lab.getByRole('status');

  await typeCode(page, HOARDER);
  await run.click();
  // The page answers while the worker fills its heap.
  expect(await page.evaluate(() => document.title.length)).toBeGreaterThan(0);
  // Either the time limit removes the frame, or the worker's heap runs out first and the run says it could not go on.
  await expect(result).toContainText(/Your function did not return within 2 s on case 1\.|Your code could not run: /, { timeout: 30_000 });
  expect(await page.evaluate(() => localStorage.getItem('rtq.progress'))).toContain('01-introduction');

  // The next run gets a new sandbox, and a correct function passes.
  await typeCode(page, CORRECT);
  await run.click();
  await expect(result).toContainText('306 of 306 cases pass.');
  expect(errors).toEqual([]);
});
