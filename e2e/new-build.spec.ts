import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { makeNewerBuild, startSwitchingServer, type SwitchingServer } from './support/two-builds.ts';

// A new build put on the server while a tab of the old one is open, and a tab offline
// whose code was never stored: the teacher pages and the on-demand panels either load or
// say so with a Reload button, after a few requests, never stuck on "Loading…" asking the
// server again and again (issue 38: 2,800 requests in 10 s). docs/offline.md.

const BUILD = process.env.E2E_DIST ?? 'dist';
/** One load and two more tries (src/util/lazy-module.ts). */
const MOST_TRIES = 3;

let scratch: string;
let newer: string;
let server: SwitchingServer;

test.beforeAll(async () => {
  scratch = mkdtempSync(join(tmpdir(), 'rt-two-builds-'));
  newer = join(scratch, 'newer');
  makeNewerBuild(BUILD, newer);
  server = await startSwitchingServer(BUILD);
});

test.afterAll(async () => {
  await server.close();
  rmSync(scratch, { recursive: true, force: true });
});

test.beforeEach(() => server.serve(BUILD));

/** The requests the server was sent since `from` whose path has `part` in it. */
const requestsFor = (part: string, from = 0) => server.requests.slice(from).filter((request) => request.path.includes(part));

/** Opens the game at `url` and waits until the page has loaded all it loads by itself (the 3D view and its layers come after the first screen). */
async function openGame(page: Page, url: string): Promise<void> {
  await page.goto(url);
  await expect(page.locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
  await page.waitForLoadState('networkidle');
}

const go = (page: Page, hash: string) => page.evaluate((hash) => (location.hash = hash), hash);

/** The script of the build a page runs (index.html names it). */
const buildScript = (page: Page) => page.evaluate(() => document.querySelector('script[type=module]')?.getAttribute('src') ?? '');

test.describe('with the offline copy', () => {
  test.use({ serviceWorkers: 'allow' });

  test('a tab of the old build keeps its pages and panels; the new build starts once its tabs are closed', async ({ context, page }) => {
    await openGame(page, server.url);
    await expect.poll(() => page.evaluate(() => navigator.serviceWorker.controller !== null), { timeout: 30_000 }).toBe(true);
    const oldScript = await buildScript(page);

    server.serve(newer);
    const switched = server.requests.length;
    // The browser finds the new build (it looks on every visit; here at once) and stores it beside the old one.
    await page.evaluate(async () => void (await navigator.serviceWorker.getRegistration())?.update());
    await expect
      .poll(() => page.evaluate(async () => (await navigator.serviceWorker.getRegistration())?.waiting?.state ?? null), { timeout: 30_000 })
      .toBe('installed');
    await page.getByRole('button', { name: 'Menu' }).click();
    await expect(page.getByTestId('offline-status')).toHaveText(
      /works offline.*A new version has been stored as well; it starts once every tab of this app has been closed\./,
    );
    await page.keyboard.press('Escape');

    // The old tab opens what it had not loaded yet: its own build's code, still stored.
    await go(page, '#/teacher');
    await expect(page.locator('rt-teacher-page').getByRole('heading', { name: 'Make an assignment' })).toBeVisible();
    await go(page, '#/dashboard');
    await expect(page.locator('rt-dashboard-page').getByRole('heading', { name: 'Class dashboard' })).toBeVisible();
    await go(page, '#free-lab');
    await expect(page.locator('rt-bvh-panel').getByRole('switch', { name: 'Show the BVH' })).toBeVisible();
    expect(await buildScript(page)).toBe(oldScript);
    // Nothing the old tab asked for was missing; the server was asked for the new build once.
    expect(server.requests.slice(switched).filter((request) => request.status !== 200)).toEqual([]);
    expect(server.requests.slice(switched).filter((request) => /rt-teacher-page-[\w-]+B\.js$/.test(request.path))).toHaveLength(1);

    // With every tab of the old build closed, a new tab runs the new build, its teacher page too.
    await page.close();
    await expect(async () => {
      const fresh = await context.newPage();
      await fresh.goto(server.url);
      const script = await buildScript(fresh);
      await fresh.close();
      expect(script).toMatch(/B\.js$/);
    }).toPass({ timeout: 30_000 });
    const fresh = await context.newPage();
    await fresh.goto(`${server.url}#/teacher`);
    await expect(fresh.locator('rt-teacher-page').getByRole('heading', { name: 'Make an assignment' })).toBeVisible();
  });
});

test.describe('without an offline copy', () => {
  test.use({ serviceWorkers: 'block' });

  test('a tab whose build was replaced says so with Reload after a few requests, and Reload brings the new build', async ({ page }) => {
    await openGame(page, server.url);
    server.serve(newer);
    const switched = server.requests.length;

    await go(page, '#/teacher');
    const pageProblem = page.locator('rt-load-problem');
    await expect(pageProblem).toContainText('This page could not be loaded.');
    await expect(pageProblem.getByRole('button', { name: 'Reload' })).toBeVisible();
    await go(page, '#free-lab');
    const panelProblem = page.locator('rt-lab').getByRole('alert').filter({ hasText: 'This panel could not be loaded.' });
    await expect(panelProblem).toBeVisible();
    // A few seconds more: no one asks again.
    await page.waitForTimeout(5000);
    expect(requestsFor('rt-teacher-page', switched)).toHaveLength(MOST_TRIES);
    expect(requestsFor('rt-bvh-panel', switched)).toHaveLength(MOST_TRIES);
    // The rest: the favicon, and the render workers of the lab opened again, which the
    // render pool also tries a bounded number of times (render-pool.ts; the next test).
    expect(server.requests.length - switched).toBeLessThan(40);

    await panelProblem.getByRole('button', { name: 'Reload' }).click();
    await expect(page.locator('rt-bvh-panel').getByRole('switch', { name: 'Show the BVH' })).toBeVisible();
    expect(await buildScript(page)).toMatch(/B\.js$/);
  });

  test('an old tab opening the lab again says its ray tracer, debugger and renders cannot be loaded, with Reload, after a few requests', async ({ page }) => {
    await openGame(page, server.url);
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    server.serve(newer);
    const switched = server.requests.length;
    // The lab leaves the page (its workers stop) and comes back: new workers, whose code is gone.
    await go(page, '#/teacher');
    await expect(page.locator('rt-load-problem')).toContainText('This page could not be loaded.');
    await go(page, '#free-lab');
    const problems = page.locator('rt-lab .lab-load-problems').getByRole('alert');
    await expect(problems.filter({ hasText: 'The ray tracer could not be loaded: no rays are traced and no image can be rendered.' })).toBeVisible();
    await expect(problems.filter({ hasText: 'The ray debugger could not be loaded.' }).getByRole('button', { name: 'Reload' })).toBeVisible();
    await page.getByRole('button', { name: 'Render image' }).click();
    await page.locator('rt-render-window').getByRole('button', { name: 'Render', exact: true }).click();
    const renderProblem = page.locator('rt-render-window rt-load-problem');
    await expect(renderProblem).toContainText('The render workers could not be loaded.');
    await expect(renderProblem.getByRole('button', { name: 'Reload' })).toBeVisible();
    await page.screenshot({ path: 'test-results/screens/new-build-old-tab-lab.png' });
    // Each pool tries its workers a bounded number of times (its size and two more: render-pool.ts), then no more.
    await page.waitForTimeout(4000);
    const workers = requestsFor('render.worker', switched);
    expect(workers.every((request) => request.status === 404)).toBe(true);
    expect(workers.length).toBeGreaterThanOrEqual(3);
    expect(workers.length).toBeLessThanOrEqual(cores + 2 + 3);
    // An edit traces again: at once refused by the pool, no request.
    await page
      .locator('rt-scene-view canvas')
      .press('ArrowUp')
      .catch(() => {});
    await page.waitForTimeout(3000);
    expect(requestsFor('render.worker', switched)).toHaveLength(workers.length);

    await renderProblem.getByRole('button', { name: 'Reload' }).click();
    await expect(page.locator('rt-quest-panel, rt-lab').first()).toBeVisible();
    expect(await buildScript(page)).toMatch(/B\.js$/);
    await expect(page.locator('rt-lab .lab-load-problems')).toHaveCount(0);
  });

  test('Dutch texts that cannot be loaded are said in English with Reload, and the page works in English', async ({ page }) => {
    // At the start: the Dutch texts' file does not arrive (three tries).
    const tries: string[] = [];
    await page.route(/\/assets\/nl-[\w-]+\.js$/, (route) => (tries.push(route.request().url()), route.abort()));
    await page.goto(`${server.url}?lang=nl`);
    const problem = page.locator('body > rt-load-problem.locale-problem');
    await expect(problem).toContainText('The Dutch texts could not be loaded, so the app is in English.');
    await expect(problem.getByRole('button', { name: 'Reload' })).toBeVisible();
    await expect(page.locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
    expect(await page.evaluate(() => document.documentElement.lang)).toBe('en');
    expect(tries).toHaveLength(MOST_TRIES);
    await page.screenshot({ path: 'test-results/screens/new-build-dutch-failed.png' });
    await problem.getByRole('button', { name: 'Close' }).click();
    await expect(problem).toHaveCount(0);
    await page.unroute(/\/assets\/nl-[\w-]+\.js$/);

    // An old tab after a new build: Dutch chosen in the Menu asks for the old file, which is gone.
    await page.goto(server.url);
    await expect(page.locator('rt-quest-panel').getByRole('heading', { name: 'Introduction' })).toBeVisible();
    server.serve(newer);
    const switched = server.requests.length;
    await page.getByRole('button', { name: 'Menu' }).click();
    await page.getByRole('radio', { name: 'Nederlands' }).check();
    await expect(problem).toContainText('The Dutch texts could not be loaded, so the app is in English.');
    expect(requestsFor('/assets/nl-', switched)).toHaveLength(MOST_TRIES);
    await expect(page.getByRole('button', { name: 'Menu' })).toBeVisible();
    expect(await page.evaluate(() => document.documentElement.lang)).toBe('en');
  });

  test('offline, a page never loaded says so with Reload after a few tries', async ({ context, page }) => {
    await openGame(page, server.url);
    const tries: string[] = [];
    page.on('request', (request) => {
      if (/rt-dashboard-page|rt-bvh-panel/.test(request.url())) tries.push(new URL(request.url()).pathname);
    });
    await context.setOffline(true);

    await go(page, '#/dashboard');
    await expect(page.locator('p.loading')).toHaveText('Loading…');
    const problem = page.locator('rt-load-problem');
    await expect(problem).toContainText('This page could not be loaded.');
    await expect(problem.getByRole('button', { name: 'Reload' })).toBeVisible();
    await go(page, '#free-lab');
    await expect(page.locator('rt-lab').getByRole('alert').filter({ hasText: 'This panel could not be loaded.' })).toBeVisible();
    await page.waitForTimeout(5000);
    expect(tries.filter((path) => path.includes('rt-dashboard-page'))).toHaveLength(MOST_TRIES);
    expect(tries.filter((path) => path.includes('rt-bvh-panel'))).toHaveLength(MOST_TRIES);

    // Online again, the page comes with a reload.
    await context.setOffline(false);
    await go(page, '#/dashboard');
    await page.locator('rt-load-problem').getByRole('button', { name: 'Reload' }).click();
    await expect(page.locator('rt-dashboard-page').getByRole('heading', { name: 'Class dashboard' })).toBeVisible();
  });
});
