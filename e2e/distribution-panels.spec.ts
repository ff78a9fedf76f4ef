import { expect, test, type Page } from '@playwright/test';
import type { LabState } from '../src/lab-state/lab-state.ts';
import { expectAccessible } from './support/axe.ts';
import { collectErrors } from './support/game-steps.ts';

// The controls of distributed ray tracing, used as a student would, in the free lab: open
// the lens (aperture, lens samples), focus on the selected object, roughen the mirror ball,
// set the red ball moving (movement, time samples). After each, the 3D view draws something
// else: more rays (its `data-ray-instances`, the ray pool's cylinders, and
// `data-cone-instances`) or, for the movement, other pixels on the canvas (the ball's copies
// in time). Last, axe-core with those panels open: no serious or critical violation.

async function state(page: Page): Promise<LabState> {
  return page.evaluate(() => (document.querySelector('rt-lab') as unknown as { store: { state: LabState } }).store.state);
}

const view = (page: Page) => page.locator('[data-ray-instances]').first();

async function drawnRays(page: Page): Promise<number> {
  return Number(await view(page).getAttribute('data-ray-instances'));
}

/** Types `value` into the typed box of the slider `name` in `panel` and presses Enter. */
async function typeInto(page: Page, panel: string, label: string, value: string): Promise<void> {
  const field = page.locator(panel).getByRole('textbox', { name: `${label}, typed value` });
  await field.scrollIntoViewIfNeeded();
  await field.fill(value);
  await field.press('Enter');
}

/**
 * Waits until the view draws more than `before` rays (at least `atLeast`: the scene is traced
 * again, then drawn); each field typed is a scene of its own, so an early count can be the
 * first field's alone.
 */
async function expectMoreRays(page: Page, before: number, what: string, atLeast = before + 1): Promise<number> {
  await expect
    .poll(() => drawnRays(page), { message: `${what}: the view draws more rays`, timeout: 60_000 })
    .toBeGreaterThanOrEqual(Math.max(before + 1, atLeast));
  return drawnRays(page);
}

test('aperture, roughness and movement set in the panels change what the 3D view draws; axe finds nothing serious', async ({ page }) => {
  // axe's contrast rule walks every element in two themes: minutes on a busy school machine.
  test.slow();
  const errors = collectErrors(page);
  await page.goto('./#free-lab');
  await expect(view(page)).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 60_000 });
  const pinhole = await drawnRays(page);

  // The lens: a wider aperture, 2 × 2 lens rays for every pixel sample.
  await typeInto(page, 'rt-tracer-panel', 'Aperture (lens radius)', '0.2');
  await typeInto(page, 'rt-tracer-panel', 'Lens samples (n)', '2');
  expect((await state(page)).scene.camera).toMatchObject({ aperture: 0.2, lensSamples: 2 });
  // 2 × 2 lens rays where there was one primary: at least 3 times the rays once both fields are in.
  const withLens = await expectMoreRays(page, pinhole, 'lens samples 2 at aperture 0.2', pinhole * 3);

  // Focus on the selected object: the plane in focus goes through the red ball's centre.
  const list = page.locator('rt-scene-list');
  await list.getByRole('option', { name: /Red ball/ }).click();
  await page
    .locator('rt-tracer-panel')
    .getByRole('button', { name: /^Focus on / })
    .click();
  const { camera } = (await state(page)).scene;
  const forward = camera.target.map((t, axis) => t - camera.position[axis]);
  const along = [-1.5, 0.5, 0.3].reduce((sum, p, axis) => sum + (p - camera.position[axis]) * forward[axis], 0) / Math.hypot(...forward);
  expect(camera.focusDistance).toBeCloseTo(along, 6);

  // Gloss: the mirror ball's one reflected ray per hit becomes a fan of 3 × 3.
  await list.getByRole('option', { name: /Mirror ball/ }).click();
  await typeInto(page, 'rt-object-panel', 'Roughness (ρ)', '0.3');
  expect((await state(page)).scene.objects.find((o) => o.id === 'mirror-ball')!.material.roughness).toBe(0.3);
  const glossy = await expectMoreRays(page, withLens, 'roughness 0.3 on the mirror ball');

  // Motion: the red ball moves 1 m right while the shutter is open; its copy in time is drawn.
  await list.getByRole('option', { name: /Red ball/ }).click();
  const canvas = page.locator('rt-scene-view canvas').first();
  const still = await canvas.screenshot();
  const x = page.locator('rt-object-panel').getByRole('textbox', { name: 'Movement while the shutter is open x' });
  await x.scrollIntoViewIfNeeded();
  await x.fill('1');
  await x.press('Enter');
  expect((await state(page)).scene.objects.find((o) => o.id === 'red-ball')!.velocity).toEqual([1, 0, 0]);
  await expect.poll(async () => Buffer.compare(await canvas.screenshot(), still) !== 0, { message: 'the moving ball is drawn differently' }).toBe(true);
  await typeInto(page, 'rt-tracer-panel', 'Time samples (k)', '2');
  expect((await state(page)).scene.settings.timeSamples).toBe(2);
  await expectMoreRays(page, glossy, 'time samples 2');

  // The object panel (red ball: roughness, movement) and the ray tracer panel (lens and shutter) are open.
  await expect(page.locator('rt-object-panel').getByRole('slider', { name: 'Roughness (ρ)' })).toBeVisible();
  await expectAccessible(page, 'the free lab with the lens, gloss and movement set');
  expect(errors).toEqual([]);
});
