import { expect, test, type Page } from '@playwright/test';
import { readFile } from 'node:fs/promises';
import type { LabAction } from '../src/lab-state/lab-action.ts';
import type { Scene } from '../src/scene/scene.ts';

// The sandbox's save, load and share: a scene saved as a file comes back the same; a file
// that is not a scene leaves the scene alone with a message (in Dutch too, as is a progress
// file's); a shared link opens the scene in the free lab, and a damaged link says so.

type Recorded = Window & { actions: string[] };

async function scene(page: Page): Promise<Scene> {
  return page.evaluate(() => (document.querySelector('rt-lab') as unknown as { store: { state: { scene: Scene } } }).store.state.scene);
}

async function dispatch(page: Page, action: LabAction): Promise<void> {
  await page.evaluate((sent) => (document.querySelector('rt-lab') as unknown as { store: { dispatch(action: LabAction): void } }).store.dispatch(sent), action);
}

/** The lab's free lab, with the store's action types recorded in `window.actions`. */
async function openFreeLab(page: Page): Promise<void> {
  await page.goto('./');
  await page.locator('rt-lab').getByRole('button', { name: 'Levels' }).click();
  await page.locator('rt-lab').getByRole('button', { name: 'Free lab' }).click();
  await expect(page.locator('rt-file-panel')).toBeVisible();
  await page.evaluate(() => {
    (window as unknown as Recorded).actions = [];
    (document.querySelector('rt-lab') as unknown as { store: { subscribe(listener: (state: unknown, action: LabAction) => void): void } }).store.subscribe(
      (_state, action) => (window as unknown as Recorded).actions.push(action.type === 'scene.saved' ? `scene.saved:${action.to}` : action.type),
    );
  });
}

const recorded = (page: Page) => page.evaluate(() => (window as unknown as Recorded).actions);

test('save a scene as a file and load it back; a broken file changes nothing', async ({ page }) => {
  await openFreeLab(page);
  const panel = page.locator('rt-file-panel');
  const saved = await scene(page);

  const downloading = page.waitForEvent('download');
  await panel.getByRole('button', { name: 'Save as file' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe('three-spheres-and-a-box.scene.json');
  const text = await readFile(await download.path(), 'utf8');
  expect(JSON.parse(text)).toEqual(saved);
  await expect(panel.getByRole('status')).toContainText('Saved as three-spheres-and-a-box.scene.json');
  expect(await recorded(page)).toContain('scene.saved:file');

  await dispatch(page, { type: 'object.deleted', id: 'red-ball' });
  expect((await scene(page)).objects.map((object) => object.id)).not.toContain('red-ball');

  const input = panel.locator('input[type=file]');
  await input.setInputFiles({ name: 'three-spheres-and-a-box.scene.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await expect(panel.getByRole('status')).toHaveText(/Loaded Three spheres and a box\./);
  expect(await scene(page)).toEqual(saved);
  expect(await recorded(page)).toContain('scene.loaded');

  const broken = JSON.stringify({ ...saved, camera: { ...saved.camera, fov: 500 } });
  await input.setInputFiles({ name: 'wide.scene.json', mimeType: 'application/json', buffer: Buffer.from(broken) });
  await expect(panel.getByRole('status')).toContainText('wide.scene.json is not a scene file this app can open; your scene is unchanged.');
  await expect(panel.getByRole('status')).toContainText('camera.fov:');
  await input.setInputFiles({ name: 'notes.json', mimeType: 'application/json', buffer: Buffer.from('{"version": 1,') });
  await expect(panel.getByRole('status')).toContainText('not valid JSON at line 1');
  expect(await scene(page)).toEqual(saved);

  // In Dutch the detail lines are Dutch too, not only the sentence around them.
  await page.goto('./?lang=nl#free-lab');
  await panel.locator('input[type=file]').setInputFiles({ name: 'wide.scene.json', mimeType: 'application/json', buffer: Buffer.from(broken) });
  await expect(panel.getByRole('status')).toContainText('wide.scene.json is geen scènebestand');
  await expect(panel.getByRole('status')).toContainText('camera.fov: moet tussen 1 en 179 liggen, maar is 500');
  await panel.locator('input[type=file]').setInputFiles({ name: 'notes.json', mimeType: 'application/json', buffer: Buffer.from('{"version": 1,') });
  await expect(panel.getByRole('status')).toContainText(
    '(het geheel): geen geldige JSON op regel 1, kolom 15: verwacht werd een veldnaam tussen dubbele aanhalingstekens',
  );
  await page.screenshot({ path: 'test-results/screens/scene-file-broken-nl.png' });

  // So are a progress file's reasons (the patterns for them load with the Dutch texts).
  await page.getByRole('button', { name: 'Menu' }).click();
  const progress = JSON.stringify({ kind: 'ray-tracer-quest-progress', version: 7 });
  await page
    .locator('rt-progress-menu input[type=file]')
    .setInputFiles({ name: 'voortgang.json', mimeType: 'application/json', buffer: Buffer.from(progress) });
  await expect(page.locator('rt-toast')).toContainText('version: deze app leest voortgang van versie 1, maar de versie is 7');
  await page.screenshot({ path: 'test-results/screens/progress-file-broken-nl.png' });
});

test('a shared link opens the scene in the free lab; a damaged link says why', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await openFreeLab(page);
  const shared = { ...(await scene(page)), name: 'Our shared scene' };
  shared.objects = shared.objects.filter((object) => object.id !== 'mirror-ball');
  await dispatch(page, { type: 'scene.loaded', scene: shared });

  const panel = page.locator('rt-file-panel');
  await panel.getByRole('button', { name: 'Share link' }).click();
  const field = panel.getByRole('textbox', { name: 'Link to this scene' });
  await expect(field).toHaveValue(/#\/s\/[A-Za-z0-9_-]+$/);
  const link = await field.inputValue();
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(link);
  await expect(panel.getByRole('status')).toContainText('The link is copied');
  expect(await recorded(page)).toContain('scene.saved:link');

  const other = await context.newPage();
  await other.goto(link);
  await expect(other.locator('rt-lab[free-lab]')).toBeAttached();
  await expect.poll(async () => (await scene(other)).name).toBe('Our shared scene');
  expect(await scene(other)).toEqual(shared);
  await expect(other.locator('rt-file-panel')).toBeVisible();

  const cut = link.slice(0, link.length - 12);
  await other.goto('about:blank');
  await other.goto(cut);
  await expect(other.locator('rt-link-notice')).toContainText('This scene link is damaged');
  await expect(other.locator('rt-lab')).toBeAttached();
  expect((await scene(other)).name).not.toBe('Our shared scene');
});
