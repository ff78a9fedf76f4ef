import { expect, test, type Page } from '@playwright/test';
import { collectErrors, expectStatus, progressFile } from './support/game-steps.ts';

// The first code lab (issue 43): a correct hitSphere passes every case and completes the task;
// the learner's code cannot reach the page, the stored progress or the network; an endless
// loop is stopped after 2 s with a message while the page stays responsive, and the next Run works.

const LEVEL = '02-rays-from-the-camera';
const TITLE = 'Code lab: where does a ray hit the ball?';

const CORRECT = `function hitSphere(origin, direction, center, radius) {
  const oc = sub(origin, center);
  const a = dot(direction, direction);
  const b = 2 * dot(oc, direction);
  const c = dot(oc, oc) - radius * radius;
  const d = b * b - 4 * a * c;
  if (d < 0) return null;
  const near = (-b - Math.sqrt(d)) / (2 * a);
  if (near > 0) return near;
  const far = (-b + Math.sqrt(d)) / (2 * a);
  return far > 0 ? far : null;
}`;

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

type ShownCase = { points: { mark: string }[]; shapes: unknown[] } | null;
const shownCase = (page: Page) =>
  page.locator('rt-scene-view').evaluate((element) => (element as unknown as { labView: { labCase: { shown: ShownCase } } }).labView.labCase.shown);

const ENDLESS = `function hitSphere() {
  while (true) {}
}`;

async function typeCode(page: Page, code: string): Promise<void> {
  const editor = page.locator('rt-code-lab .cm-content');
  await editor.click();
  await page.keyboard.press('ControlOrMeta+a');
  await page.keyboard.insertText(code);
}

test('a code lab grades a correct function, and hostile code reaches nothing and is stopped', async ({ page }) => {
  const errors = collectErrors(page);
  await page.addInitScript(
    (saved) => {
      // Init scripts run in every frame: the sandbox's has no storage at all.
      if (window !== window.top || sessionStorage.getItem('seeded')) return;
      sessionStorage.setItem('seeded', 'yes');
      localStorage.setItem('rtq.progress', saved);
    },
    progressFile(['01-introduction']),
  );
  await page.goto('/');
  const welcome = page.getByRole('button', { name: 'Got it' });
  if (await welcome.count()) await welcome.click();
  await page.locator('[data-command="levels"]').click();
  await page.locator(`rt-level-map [data-level="${LEVEL}"]`).click();
  await page.locator('rt-task-card[data-task="code-hit-sphere"] button.head').click();
  const lab = page.locator('rt-code-lab');
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

  await typeCode(page, CORRECT);
  await run.click();
  await expect(result).toContainText('306 of 306 cases pass.');
  expect(await shownCase(page)).toBeNull();
  await expectStatus(page, TITLE, 'done');
  // The code is kept for the next visit.
  expect(await page.evaluate(() => localStorage.getItem('rtq.code-lab.ray-sphere'))).toContain('const oc = sub(origin, center);');
  expect(errors).toEqual([]);
});
