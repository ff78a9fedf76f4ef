import { expect, test, type Page } from '@playwright/test';
import type { LabState } from '../src/lab-state/lab-state.ts';

// The lab's panels, used as a student would: select in the scene list, edit, type wrong
// things, use presets and the keyboard. The state is read from the store that <rt-lab> exposes.

async function state(page: Page): Promise<LabState> {
  return page.evaluate(() => (document.querySelector('rt-lab') as unknown as { store: { state: LabState } }).store.state);
}

async function openLab(page: Page, errors: string[]): Promise<void> {
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('./#free-lab');
  await expect(page.locator('rt-scene-list').getByRole('option').first()).toBeVisible();
}

test('select an object in the scene list and change its colour', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  const list = page.locator('rt-scene-list');
  await list.getByRole('option', { name: /Red ball/ }).click();
  expect((await state(page)).selection).toEqual({ kind: 'object', id: 'red-ball' });

  const panel = page.locator('rt-object-panel');
  const hex = panel.getByRole('textbox', { name: 'Colour, hex code' });
  await expect(hex).toHaveValue('#e6261a');
  await hex.fill('#00ff00');
  await hex.press('Enter');
  const ball = (s: LabState) => s.scene.objects.find((o) => o.id === 'red-ball')!;
  expect(ball(await state(page)).material.color).toEqual([0, 1, 0]);

  // Unreadable colour text: a message, and the colour stays.
  await hex.fill('green');
  await hex.press('Enter');
  await expect(panel.getByRole('status').filter({ hasText: 'Type a colour as #rrggbb' })).toBeVisible();
  expect(ball(await state(page)).material.color).toEqual([0, 1, 0]);

  // Select something else and come back: the field shows the store's colour.
  await list.getByRole('option', { name: /Box/ }).click();
  await expect(hex).toHaveValue('#3366e6');
  await list.getByRole('option', { name: /Red ball/ }).click();
  await expect(hex).toHaveValue('#00ff00');
  expect(errors).toEqual([]);
});

test('typed numbers: clamped with a message, unreadable text keeps the value', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  await page.locator('rt-scene-list').getByRole('option', { name: /Spot / }).click();
  const slider = page.locator('rt-light-panel rt-slider[name="spotAngle"]');
  const field = slider.getByRole('textbox', { name: 'Spot angle, typed value' });
  const spotAngle = async () => (await state(page)).scene.lights.find((l) => l.id === 'spot')!;

  await field.fill('400');
  await field.press('Enter');
  await expect(slider.getByRole('status')).toHaveText(/Clamped to 1–170/);
  await expect(field).toHaveValue('170');
  expect(await spotAngle()).toMatchObject({ spotAngle: 170 });

  await field.fill('abc');
  await field.press('Tab');
  await expect(slider.getByRole('status')).toHaveText(/Type a number between 1 and 170/);
  await expect(field).toHaveValue('170');
  expect(await spotAngle()).toMatchObject({ spotAngle: 170 });

  // A decimal comma, then the range's keys: one step per Arrow, End to the top.
  await field.fill('45,5');
  await field.press('Enter');
  expect(await spotAngle()).toMatchObject({ spotAngle: 45.5 });
  const range = slider.getByRole('slider', { name: 'Spot angle' });
  await range.focus();
  await range.press('Home');
  await range.press('ArrowRight');
  expect(await spotAngle()).toMatchObject({ spotAngle: 2 });
  await range.press('End');
  expect(await spotAngle()).toMatchObject({ spotAngle: 170 });
  expect(errors).toEqual([]);
});

test('the Glass preset makes the object transparent and enables its refractive index', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  await page
    .locator('rt-scene-list')
    .getByRole('option', { name: /Red ball/ })
    .click();
  const panel = page.locator('rt-object-panel');
  const index = panel.getByRole('slider', { name: 'Refractive index (η)' });
  await expect(index).toBeDisabled();
  await panel.getByRole('button', { name: 'Glass' }).click();
  const material = (await state(page)).scene.objects.find((o) => o.id === 'red-ball')!.material;
  expect(material).toMatchObject({ transparent: true, refractiveIndex: 1.5, specular: 0.6 });
  expect(material.color).toEqual([0.9, 0.15, 0.1]);
  await expect(panel.getByRole('button', { name: /Glass/ })).toHaveAttribute('aria-pressed', 'true');
  await expect(panel.getByRole('switch', { name: 'Transparent' })).toBeChecked();
  await expect(index).toBeEnabled();
  expect(errors).toEqual([]);
});

test('the scene list by keyboard: arrows select, Add and Delete', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  const list = page.locator('rt-scene-list');
  await list.getByRole('option', { name: /Floor/ }).click();
  await page.keyboard.press('ArrowDown');
  expect((await state(page)).selection).toEqual({ kind: 'object', id: 'red-ball' });
  await expect(list.getByRole('option', { name: /Red ball/ })).toBeFocused();
  await page.keyboard.press('End');
  expect((await state(page)).selection).toEqual({ kind: 'camera' });

  await list.getByRole('button', { name: 'Add' }).click();
  await list.getByRole('group', { name: 'Lights' }).getByRole('button', { name: 'Spot' }).click();
  const added = await state(page);
  expect(added.scene.lights.map((l) => l.id)).toContain('spot-1');
  expect(added.selection).toEqual({ kind: 'light', id: 'spot-1' });
  await expect(list.getByRole('option', { name: /Spot light 1/ })).toBeFocused();
  await page.keyboard.press('Delete');
  expect((await state(page)).scene.lights.map((l) => l.id)).not.toContain('spot-1');
  expect(errors).toEqual([]);
});

test('every control of the object panel can be reached by Tab and shows its focus', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  await page
    .locator('rt-scene-list')
    .getByRole('option', { name: /Red ball/ })
    .click();
  await page.locator('rt-object-panel rt-color-field input[type="color"]').focus();

  const stops: { label: string; ring: boolean; panel: boolean }[] = [];
  for (let i = 0; i < 40; i++) {
    await page.keyboard.press('Tab');
    stops.push(
      await page.evaluate(() => {
        // The focused element inside the shadow roots.
        let active = document.activeElement;
        while (active?.shadowRoot?.activeElement) active = active.shadowRoot.activeElement;
        // A ring on it or on the box drawn around it (the slider's number field with its unit).
        const ring = [active, active?.parentElement].some((el) => {
          if (!el) return false;
          const style = getComputedStyle(el);
          return style.outlineStyle !== 'none' && parseFloat(style.outlineWidth) >= 2;
        });
        let node: Node | null = active;
        let panel = false;
        while (node && !panel) {
          panel = node instanceof Element && node.localName === 'rt-object-panel';
          const root = node.getRootNode();
          node = node.parentNode instanceof Element ? node.parentNode : root instanceof ShadowRoot ? root.host : null;
        }
        return { label: active?.getAttribute('aria-label') ?? active?.textContent?.trim() ?? '', ring, panel };
      }),
    );
  }
  const inPanel = stops.filter((stop) => stop.panel);
  const labels = inPanel.map((stop) => stop.label);
  for (const label of ['Colour, hex code', 'Ambient (ka)', 'Shininess (n), typed value', 'Position x', 'Scale z']) expect(labels).toContain(label);
  expect(inPanel.filter((stop) => !stop.ring)).toEqual([]);
  expect(errors).toEqual([]);
});

test('dragging a slider changes the store before the release; a change elsewhere shows in the fields', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  await page
    .locator('rt-scene-list')
    .getByRole('option', { name: /Red ball/ })
    .click();
  const panel = page.locator('rt-object-panel');
  const shininess = async () => (await state(page)).scene.objects.find((o) => o.id === 'red-ball')!.material.shininess;
  const slider = panel.getByRole('slider', { name: 'Shininess (n)' });
  await slider.scrollIntoViewIfNeeded();
  const box = (await slider.boundingBox())!;
  await page.mouse.move(box.x + 10, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 5 });
  await expect.poll(shininess).toBeGreaterThan(300);
  await page.mouse.up();
  await expect(panel.getByRole('textbox', { name: 'Shininess (n), typed value' })).toHaveValue(String(await shininess()));

  // As the gizmo would: the store changes, the fields follow.
  await page.evaluate(() => {
    const lab = document.querySelector('rt-lab') as unknown as { store: { dispatch(action: unknown): string | undefined } };
    lab.store.dispatch({ type: 'object.changed', id: 'red-ball', changes: { position: [1.25, 0.5, -2] } });
  });
  await expect(panel.getByRole('textbox', { name: 'Position x' })).toHaveValue('1.25');
  await expect(panel.getByRole('textbox', { name: 'Position z' })).toHaveValue('-2.00');
  expect(errors).toEqual([]);
});

test('a change the store refuses is explained next to the control and nothing breaks', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  // A scene already holding the most lights a scene may have.
  await page.evaluate(() => {
    const lab = document.querySelector('rt-lab') as unknown as { store: { state: LabState; dispatch(action: unknown): string | undefined } };
    const scene = lab.store.state.scene;
    const lights = Array.from({ length: 32 }, (_, i) => ({ ...scene.lights[0], id: `lamp-${i}` }));
    lab.store.dispatch({ type: 'scene.loaded', scene: { ...scene, lights } });
  });
  const list = page.locator('rt-scene-list');
  await list.getByRole('button', { name: 'Add' }).click();
  await list.getByRole('group', { name: 'Lights' }).getByRole('button', { name: 'Point' }).click();
  await expect(list.getByRole('status').filter({ hasText: /lights: must have at most 32/ })).toBeVisible();
  expect((await state(page)).scene.lights).toHaveLength(32);
  // Still working: select and edit.
  await list.getByRole('option', { name: /Red ball/ }).click();
  await expect(page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' })).toHaveValue('#e6261a');
  expect(errors).toEqual([]);
});

test('a closed section stays closed after a reload', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  await page
    .locator('rt-scene-list')
    .getByRole('option', { name: /Red ball/ })
    .click();
  const position = page.locator('rt-object-panel').getByRole('textbox', { name: 'Position x' });
  await expect(position).toBeVisible();
  await page.locator('rt-object-panel rt-panel-section[name="object-placement"] summary').click();
  await expect(position).toBeHidden();
  await page.reload();
  await page
    .locator('rt-scene-list')
    .getByRole('option', { name: /Red ball/ })
    .click();
  await expect(page.locator('rt-object-panel').getByRole('textbox', { name: 'Colour, hex code' })).toBeVisible();
  await expect(position).toBeHidden();
  expect(errors).toEqual([]);
});

test('on a 1024×768 tablet every control is at least 32 px high for a finger', async ({ page }) => {
  await page.setViewportSize({ width: 1024, height: 768 });
  const errors: string[] = [];
  await openLab(page, errors);
  await page.locator('rt-scene-list').getByRole('button', { name: 'Add' }).click();
  const small: string[] = [];
  for (const item of [/Red ball/, /Spot /]) {
    await page.locator('rt-scene-list').getByRole('option', { name: item }).click();
    small.push(...(await page.evaluate(measureTargets)));
  }
  expect(small).toEqual([]);
  expect(errors).toEqual([]);
});

/** The controls in the panels' shadow roots lower than 32 px, measured by what a finger can hit (a control's label if it has one). */
function measureTargets(): string[] {
  const found: string[] = [];
  const visit = (root: ShadowRoot) => {
    for (const el of root.querySelectorAll<HTMLElement>('*')) {
      if (el.shadowRoot) visit(el.shadowRoot);
      if (!el.matches('input, button, summary, [role="option"]')) continue;
      const rect = (el.closest('label') ?? el).getBoundingClientRect();
      if (rect.width > 0 && rect.height < 31.5) found.push(`${el.localName}[${el.getAttribute('aria-label') ?? el.textContent?.trim()}]: ${rect.height}px`);
    }
  };
  for (const tag of ['rt-scene-list', 'rt-object-panel', 'rt-light-panel', 'rt-tracer-panel']) {
    const root = document.querySelector(tag)?.shadowRoot;
    if (root) visit(root);
  }
  return found;
}

test('changing a light’s type by keyboard converts it and shows that type’s controls', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  await page.locator('rt-scene-list').getByRole('option', { name: /Spot / }).click();
  const panel = page.locator('rt-light-panel');
  await expect(panel.getByRole('slider', { name: 'Spot angle' })).toBeVisible();
  await panel.getByRole('radio', { name: 'Spot' }).focus();
  await page.keyboard.press('ArrowRight');
  const light = (await state(page)).scene.lights.find((l) => l.id === 'spot')!;
  expect(light).toMatchObject({ type: 'area', samples: 3, position: [-1.5, 3, 0.3] });
  await expect(panel.getByRole('radio', { name: 'Area' })).toBeChecked();
  await expect(panel.getByRole('radio', { name: 'Area' })).toBeFocused();
  await expect(panel.getByRole('slider', { name: 'Spot angle' })).toHaveCount(0);
  await expect(panel.locator('rt-slider[name="samples"]')).toContainText('3 × 3 = 9 shadow rays per point');
  expect(errors).toEqual([]);
});

test('ray tracer settings: typed values beyond the slider, light types, sample points', async ({ page }) => {
  const errors: string[] = [];
  await openLab(page, errors);
  const panel = page.locator('rt-tracer-panel');
  const supersampling = panel.getByRole('textbox', { name: 'Supersampling (s), typed value' });
  await supersampling.fill('8');
  await supersampling.press('Enter');
  await expect(panel.locator('rt-slider[name="supersampling"]')).toContainText('8 × 8 = 64 rays per pixel');
  const columns = panel.getByRole('textbox', { name: 'Pixel columns, typed value' });
  await columns.fill('100');
  await columns.press('Enter');
  await expect(panel.locator('rt-slider[name="pixels.columns"]').getByRole('status')).toHaveText(/Clamped to 1–64/);
  await panel.getByRole('switch', { name: 'Spot lights' }).click();
  await panel.getByRole('switch', { name: 'Show sample points' }).click();
  const s = await state(page);
  expect(s.scene.settings).toMatchObject({ supersampling: 8, lightTypes: { point: true, spot: false, area: true } });
  expect(s.scene.camera.pixels).toEqual([64, 6]);
  expect(s.rays.showSamplePoints).toBe(true);
  await expect(page.locator('rt-scene-list').getByRole('option', { name: /Spot / })).toContainText('(off)');
  expect(errors).toEqual([]);
});
