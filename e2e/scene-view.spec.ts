import { expect, type Locator, type Page, test } from '@playwright/test';
import { PNG } from 'pngjs';
import { type Mesh, type MeshBasicMaterial, Quaternion, Vector3 } from 'three';
import type { LabState } from '../src/lab-state/lab-state.ts';
import type { Vec3 } from '../src/scene/scene.ts';
import { CameraRays } from '../src/tracer/camera-rays.ts';
import type { RtSceneView } from '../src/ui/lab/rt-scene-view.ts';
import { cameraRigQuaternion, cellCenter, screenGrid } from '../src/view/screen-grid.ts';
import { cameraViewFov } from '../src/view/view-pose.ts';

// The lab's 3D view as a student uses it: by mouse, keys and the on-screen buttons.
// The store is read through the element (rt-scene-view's `store`); the picture through
// screenshots of the canvas (WebGL runs on SwiftShader here, so these are real pixels).

let errors: string[] = [];

test.beforeEach(async ({ page }) => {
  errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('./#free-lab');
  const view = page.locator('rt-scene-view');
  await expect(view).toBeVisible();
  await expect.poll(() => view.evaluate((element: RtSceneView) => element.labView?.frameCount ?? 0)).toBeGreaterThan(0);
  // Every action the store hears from now on, by type.
  await view.evaluate((element: RtSceneView) => {
    const log: string[] = [];
    (window as unknown as { viewActions: string[] }).viewActions = log;
    element.store!.subscribe((_state, action, error) => log.push(error ? `${action.type} (refused)` : action.type));
  });
});

test.afterEach(() => {
  expect(errors).toEqual([]);
});

function sceneView(page: Page): Locator {
  return page.locator('rt-scene-view');
}

function canvas(page: Page): Locator {
  return page.locator('rt-scene-view canvas');
}

function appState(page: Page): Promise<LabState> {
  return sceneView(page).evaluate((element: RtSceneView) => element.store!.state);
}

/** The actions dispatched since the last call (and forgets them). */
function takeActions(page: Page): Promise<string[]> {
  return page.evaluate(() => (window as unknown as { viewActions: string[] }).viewActions.splice(0));
}

/** Where a world point is on the page. */
async function onPage(page: Page, point: Vec3): Promise<{ x: number; y: number }> {
  const box = (await canvas(page).boundingBox())!;
  const at = await sceneView(page).evaluate((element: RtSceneView, p) => element.labView!.projectToView(p), point);
  expect(at).not.toBeNull();
  return { x: box.x + at!.x, y: box.y + at!.y };
}

/** The canvas's pixels as the page shows them. */
async function picture(page: Page): Promise<PNG> {
  const box = (await canvas(page).boundingBox())!;
  // A frame to settle (an animation step, a resize) before the shot.
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  return PNG.sync.read(await page.screenshot({ clip: box }));
}

function distinctColours(png: PNG): number {
  const colours = new Set<number>();
  for (let i = 0; i < png.data.length; i += 4) colours.add((png.data[i]! << 16) | (png.data[i + 1]! << 8) | png.data[i + 2]!);
  return colours.size;
}

/** The share of pixels that differ noticeably between two same-sized pictures. */
function changedShare(a: PNG, b: PNG): number {
  let changed = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    const d = Math.abs(a.data[i]! - b.data[i]!) + Math.abs(a.data[i + 1]! - b.data[i + 1]!) + Math.abs(a.data[i + 2]! - b.data[i + 2]!);
    if (d > 24) changed++;
  }
  return changed / (a.data.length / 4);
}

/** A point of the canvas, not under an overlay, where a click hits nothing (the sky or the grid beyond the floor). */
async function emptySpace(page: Page): Promise<{ x: number; y: number }> {
  const found = await sceneView(page).evaluate((element: RtSceneView) => {
    const canvas = element.shadowRoot!.querySelector('canvas')!;
    const box = canvas.getBoundingClientRect();
    const topmost = (x: number, y: number): Element | null => {
      let hit = document.elementFromPoint(x, y);
      while (hit?.shadowRoot) {
        const inner = hit.shadowRoot.elementFromPoint(x, y);
        if (!inner || inner === hit) break;
        hit = inner;
      }
      return hit;
    };
    for (let v = 0.15; v < 0.9; v += 0.05) {
      for (let u = 0.1; u < 0.9; u += 0.05) {
        const x = box.left + u * box.width;
        const y = box.top + v * box.height;
        if (topmost(x, y) === canvas && element.labView!.pickAt(x, y) === null) return { x, y };
      }
    }
    return null;
  });
  expect(found).not.toBeNull();
  return found!;
}

function frames(page: Page): Promise<number> {
  return sceneView(page).evaluate((element: RtSceneView) => element.labView!.frameCount);
}

/** The centre of a screen pixel in the world (the same maths the view draws it with). */
function pixelCentre(state: LabState, x: number, y: number): Vec3 {
  const camera = state.scene.camera;
  const rays = new CameraRays(camera);
  const local = cellCenter(screenGrid(camera), x, y, new Vector3());
  return local.applyQuaternion(cameraRigQuaternion(rays, new Quaternion())).add(rays.eye).toArray();
}

test('draws the scene: objects with their colours, the lights, the camera and its screen', async ({ page }) => {
  const png = await picture(page);
  expect(distinctColours(png)).toBeGreaterThan(300);
  // The red ball is there in red.
  let red = 0;
  for (let i = 0; i < png.data.length; i += 4) if (png.data[i]! > 150 && png.data[i + 1]! < 70 && png.data[i + 2]! < 70) red++;
  expect(red).toBeGreaterThan(200);
  const label = await canvas(page).getAttribute('aria-label');
  expect(label).toContain('5 objects, 2 lights');
  // The gizmos keep their colours as written, the view's first ones too: three.js's colour
  // management is off before any is made (the lens's disc and edge are #7fd4ff, not linearized).
  const lensColours = await sceneView(page).evaluate((element: RtSceneView) =>
    element.labView!.scene.getObjectByName('lens')!.children.map((part) => ((part as Mesh).material as MeshBasicMaterial).color.getHexString()),
  );
  expect(lensColours).toEqual(['7fd4ff', '7fd4ff']);
  await expect(canvas(page)).toHaveAttribute('tabindex', '0');
  await page.screenshot({ path: 'test-results/screens/scene-view.png' });
});

test('orbit, pan and zoom buttons move the view; each press is reported once', async ({ page }) => {
  for (const [button, action] of [
    ['orbit-left', 'view.orbited'],
    ['orbit-up', 'view.orbited'],
    ['pan-right', 'view.panned'],
    ['zoom-in', 'view.zoomed'],
    ['zoom-out', 'view.zoomed'],
  ] as const) {
    const before = await picture(page);
    await page.locator(`rt-view-toolbar button[data-command="${button}"]`).click();
    await expect.poll(() => takeActions(page)).toEqual([action]);
    expect(changedShare(before, await picture(page)), button).toBeGreaterThan(0.05);
  }
});

test('mouse drag orbits, wheel zooms, and keys move the view, each reported once per gesture', async ({ page }) => {
  const box = (await canvas(page).boundingBox())!;
  const start = { x: box.x + box.width * 0.4, y: box.y + box.height * 0.4 };
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  await page.mouse.move(start.x + 150, start.y - 20, { steps: 12 });
  await page.mouse.up();
  await expect.poll(() => takeActions(page)).toEqual(['view.orbited']);
  for (let i = 0; i < 6; i++) await page.mouse.wheel(0, -120);
  await expect.poll(() => takeActions(page)).toEqual(['view.zoomed']);
  await canvas(page).focus();
  for (let i = 0; i < 4; i++) await page.keyboard.press('ArrowRight');
  await expect.poll(() => takeActions(page)).toEqual(['view.orbited']);
  await page.keyboard.press('Shift+ArrowUp');
  await expect.poll(() => takeActions(page)).toEqual(['view.panned']);
  await page.keyboard.press('+');
  await expect.poll(() => takeActions(page)).toEqual(['view.zoomed']);
});

test('clicking an object selects it, Escape and a click on empty space deselect', async ({ page }) => {
  const ball = await onPage(page, [-1.5, 0.5, 0.3]);
  await page.mouse.click(ball.x, ball.y);
  await expect.poll(async () => (await appState(page)).selection).toEqual({ kind: 'object', id: 'red-ball' });
  await page.keyboard.press('Escape');
  await expect.poll(async () => (await appState(page)).selection).toBeNull();

  const lamp = await onPage(page, (await appState(page)).scene.lights[1]!.position);
  await page.mouse.click(lamp.x, lamp.y);
  await expect.poll(async () => (await appState(page)).selection).toEqual({ kind: 'light', id: 'spot' });
  const sky = await emptySpace(page);
  await page.mouse.click(sky.x, sky.y);
  await expect.poll(async () => (await appState(page)).selection).toBeNull();
});

test('clicking a screen pixel shows only its rays; clicking it again shows all', async ({ page }) => {
  const cell = await onPage(page, pixelCentre(await appState(page), 1, 1));
  await page.mouse.click(cell.x, cell.y);
  await expect.poll(async () => (await appState(page)).selectedPixel).toEqual([1, 1]);
  await page.mouse.click(cell.x, cell.y);
  await expect.poll(async () => (await appState(page)).selectedPixel).toBeNull();
  expect(await takeActions(page)).toEqual(['pixel.selected', 'pixel.deselected']);
});

test('T, R, S switch the gizmo, the toolbar shows the mode pressed, and a gizmo drag moves the object once', async ({ page }) => {
  const ball = await onPage(page, [-1.5, 0.5, 0.3]);
  await page.mouse.click(ball.x, ball.y);
  await expect.poll(async () => (await appState(page)).selection).toEqual({ kind: 'object', id: 'red-ball' });
  for (const [key, mode] of [
    ['r', 'rotate'],
    ['s', 'scale'],
    ['t', 'translate'],
  ] as const) {
    await page.keyboard.press(key);
    await expect.poll(async () => (await appState(page)).gizmo.mode).toBe(mode);
    await expect(page.locator(`rt-view-toolbar button[data-command="${mode}"]`)).toHaveAttribute('aria-pressed', 'true');
  }
  await page.keyboard.press('l');
  await expect.poll(async () => (await appState(page)).gizmo.space).toBe('local');
  await takeActions(page);

  // The gizmo's centre handle moves the object in the view's plane.
  await page.mouse.move(ball.x, ball.y);
  await page.mouse.down();
  await page.mouse.move(ball.x + 60, ball.y - 40, { steps: 10 });
  await page.mouse.up();
  await expect.poll(() => takeActions(page)).toEqual(['object.changed']);
  const moved = (await appState(page)).scene.objects.find((o) => o.id === 'red-ball')!.position;
  expect(moved).not.toEqual([-1.5, 0.5, 0.3]);
  // Still selected: a drag is not a click.
  expect((await appState(page)).selection).toEqual({ kind: 'object', id: 'red-ball' });

  await page.keyboard.press('Delete');
  await expect.poll(async () => (await appState(page)).scene.objects.map((o) => o.id)).not.toContain('red-ball');
});

test('flies to the ray tracer’s camera and back', async ({ page }) => {
  const before = await sceneView(page).evaluate((element: RtSceneView) => element.labView!.camera.position.toArray());
  await page.locator('rt-view-toolbar button[data-command="fly"]').click();
  await expect.poll(() => takeActions(page)).toEqual(['view.flew-to-camera']);
  const camera = (await appState(page)).scene.camera;
  const at = await sceneView(page).evaluate((element: RtSceneView) => ({
    position: element.labView!.camera.position.toArray(),
    fov: element.labView!.camera.fov,
    aspect: element.labView!.camera.aspect,
  }));
  at.position.forEach((value, i) => expect(value).toBeCloseTo(camera.position[i]!, 4));
  // At the camera's eye, opened up just enough that its whole screen of pixels shows in this view's shape.
  expect(at.fov).toBeGreaterThanOrEqual(camera.fov);
  expect(at.fov).toBeCloseTo(cameraViewFov(camera.fov, camera.pixels[0] / camera.pixels[1], at.aspect), 6);
  await expect(page.locator('rt-view-toolbar button[data-command="fly"]')).toContainText('Back to my view');
  await page.screenshot({ path: 'test-results/screens/scene-view-camera.png' });

  await canvas(page).focus();
  await page.keyboard.press('Escape');
  await expect(page.locator('rt-view-toolbar button[data-command="fly"]')).toContainText('Camera view');
  await expect
    .poll(async () => {
      const now = await sceneView(page).evaluate((element: RtSceneView) => element.labView!.camera.position.toArray());
      return Math.hypot(now[0] - before[0], now[1] - before[1], now[2] - before[2]);
    })
    .toBeLessThan(1e-6);
});

test('the help panel opens with ? and lists every key, and Escape closes it', async ({ page }) => {
  await canvas(page).focus();
  await page.keyboard.press('?');
  const dialog = page.locator('rt-help-panel dialog');
  await expect(dialog).toBeVisible();
  for (const key of ['T', 'R', 'S', 'L', 'P', 'Page Up', 'Tab', 'Shift', 'Delete', 'Esc', 'F', '?', '+', '−']) {
    await expect(dialog.locator('kbd', { hasText: new RegExp(`^${key.replace(/[?+]/g, '\\$&')}$`) }).first()).toBeVisible();
  }
  await expect(dialog).toContainText('Pinch');
  await page.keyboard.press('Escape');
  await expect(dialog).toBeHidden();
  await page.locator('rt-view-toolbar button[data-command="help"]').click();
  await expect(dialog).toBeVisible();
  await dialog.getByRole('button', { name: 'Close' }).click();
  await expect(dialog).toBeHidden();
});

test('idle costs nothing: no frames when nothing changes or a fact is reported, and a slider drag makes no new geometry', async ({ page }) => {
  // Idle from when the camera's rays are drawn (the 3D view loads, then its rays arrive, and
  // on SwiftShader their first frame compiles shaders for a second or two): from then on a
  // whole second passes without a frame, and none is coming (a frame asked for meanwhile
  // waits for the shaders, and would land in the next check). A render loop would never get there.
  await expect(sceneView(page)).toHaveAttribute('data-ray-instances', /^[1-9]\d*$/, { timeout: 30_000 });
  const coming = () => sceneView(page).evaluate((element: RtSceneView) => !element.labView!.probes.idle);
  await expect
    .poll(
      async () => {
        const idle = await frames(page);
        await page.waitForTimeout(1000);
        return { drawn: (await frames(page)) - idle, coming: await coming() };
      },
      { timeout: 20_000 },
    )
    .toEqual({ drawn: 0, coming: false });
  // Facts the store hears (a render started and finished) change nothing drawn: no frame.
  const idle = await frames(page);
  await sceneView(page).evaluate((element: RtSceneView) => {
    element.store!.dispatch({ type: 'render.started' });
    element.store!.dispatch({ type: 'render.finished', ms: 5 });
  });
  await page.waitForTimeout(500);
  expect(await frames(page)).toBe(idle);

  const geometries = () => sceneView(page).evaluate((element: RtSceneView) => element.labView!.renderer.info.memory.geometries);
  const drag = (from: number, to: number) =>
    sceneView(page).evaluate(
      async (element: RtSceneView, [from, to]) => {
        for (let i = from; i <= to; i++) {
          element.store!.dispatch({ type: 'material.changed', id: 'red-ball', changes: { diffuse: i / 20 } });
          await new Promise((resolve) => requestAnimationFrame(resolve));
        }
      },
      [from, to],
    );
  // The drag's first step may upload a mesh that had nothing to show until then; every later
  // step reuses the pooled buffers.
  await drag(0, 0);
  const before = await geometries();
  const drawn = await frames(page);
  await drag(1, 20);
  expect(await frames(page)).toBeGreaterThan(drawn);
  expect(await geometries()).toBe(before);
});

test('the raster snapshot from the tracer’s camera leaves the on-screen view untouched', async ({ page }) => {
  const before = await picture(page);
  const snapshot = await sceneView(page).evaluate(async (element: RtSceneView) => {
    const image = await element.labView!.rasterSnapshot(128, 96);
    const colours = new Set<number>();
    let red = 0;
    for (let i = 0; i < image.data.length; i += 4) {
      colours.add((image.data[i]! << 16) | (image.data[i + 1]! << 8) | image.data[i + 2]!);
      if (image.data[i]! > 150 && image.data[i + 1]! < 70) red++;
    }
    return { width: image.width, height: image.height, colours: colours.size, red };
  });
  expect(snapshot).toMatchObject({ width: 128, height: 96 });
  expect(snapshot.colours).toBeGreaterThan(100);
  expect(snapshot.red).toBeGreaterThan(50);
  expect(changedShare(before, await picture(page))).toBe(0);
});
