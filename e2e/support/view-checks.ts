import { expect, type Page } from '@playwright/test';
import { combineViews } from '../../src/app/task-views.ts';
import type { DeclaredView } from '../../src/lab-state/lab-action.ts';
import type { ViewProbes } from '../../src/view/view-probes.ts';

/**
 * Checks of a declared view on screen (issue 9): once the view has settled, everything its
 * `frame` names is inside the 3D view's canvas and not under a panel, and the chosen
 * pixel's rays are drawn at least RAY_MIN_WIDTH px wide where they can be seen. The 3D
 * view is reached through rt-scene-view's declared `labView` and its test probes (`labView.probes`).
 */

/** The narrowest a ray may look on screen (CSS px): the shader's minimum, less a pixel for antialiasing. */
const RAY_MIN_WIDTH = 2;
/** Segments shorter than this on screen (seen end-on) are not measured across. */
const MEASURED_LENGTH = 24;

interface ViewTask {
  id: string;
  view?: DeclaredView;
}

/** The view the game applies when `task` becomes current: the level's and the task's together for the task the level opens on. */
export function viewAtStart(level: { view?: DeclaredView }, task: ViewTask, opensOnIt: boolean): DeclaredView | null {
  return opensOnIt ? combineViews(level.view, task.view) : (task.view ?? null);
}

type Point = { x: number; y: number };

/** Waits until the 3D view has arrived where a declared view sends it. */
export async function viewSettled(page: Page, where: string): Promise<void> {
  await expect
    .poll(() => page.locator('rt-scene-view').evaluate((element) => (element as unknown as { labView: { moving: boolean } | null }).labView?.moving ?? true), {
      message: `${where}: the view settles`,
      timeout: 10_000,
    })
    .toBe(false);
}

/** After viewSettled: what `view` frames is on screen, and its pixel's rays are readable. */
export async function expectViewShows(page: Page, where: string, view: DeclaredView): Promise<void> {
  const sceneView = page.locator('rt-scene-view');
  if (view.pixel !== undefined) {
    const chosen = await page
      .locator('rt-lab')
      .evaluate((lab) => (lab as unknown as { store: { state: { selectedPixel: unknown } } }).store.state.selectedPixel);
    expect(chosen, `${where}: the view chose its pixel`).toEqual(view.pixel);
  }
  const canvas = await sceneView.evaluate((element) => {
    const rect = (element as unknown as { labView: { canvas: HTMLCanvasElement } }).labView.canvas.getBoundingClientRect();
    return { left: rect.left, top: rect.top, width: rect.width, height: rect.height };
  });
  const inside = (point: Point) => point.x >= -2 && point.y >= -2 && point.x <= canvas.width + 2 && point.y <= canvas.height + 2;
  for (const name of view.frame ?? []) {
    if (name === 'pixel-rays') {
      await expectPixelRaysReadable(page, where);
      continue;
    }
    const points = await sceneView.evaluate(
      (element, framed) => (element as unknown as { labView: { probes: ViewProbes } }).labView.probes.projectedPointsOf(framed),
      name,
    );
    expect(points.length, `${where}: "${name}" has a place in the scene`).toBeGreaterThan(0);
    for (const point of points) {
      expect(point !== null && inside(point), `${where}: "${name}" is inside the 3D view (${JSON.stringify(point)} in ${canvas.width}×${canvas.height})`).toBe(
        true,
      );
    }
    const centre = { x: points.reduce((sum, p) => sum + p!.x, 0) / points.length, y: points.reduce((sum, p) => sum + p!.y, 0) / points.length };
    await expectViewAt(page, `${where}: "${name}"`, { x: canvas.left + centre.x, y: canvas.top + centre.y });
  }
}

/** Nothing covers the 3D view at this point of the page: the pointer there is over it. */
async function expectViewAt(page: Page, what: string, point: Point): Promise<void> {
  await page.mouse.move(point.x, point.y);
  expect(await page.locator('rt-scene-view').evaluate((element) => element.matches(':hover')), `${what} is not under a panel`).toBe(true);
}

/** Every ray of the chosen pixel that is long enough on screen shows at least RAY_MIN_WIDTH px across somewhere along it. */
async function expectPixelRaysReadable(page: Page, where: string): Promise<void> {
  const sceneView = page.locator('rt-scene-view');
  await expect
    .poll(() => sceneView.evaluate((element) => (element as unknown as { labView: { pixelRaySegments(): unknown[] } }).labView.pixelRaySegments().length), {
      message: `${where}: the chosen pixel's rays are traced`,
    })
    .toBeGreaterThan(0);
  const widths = await sceneView.evaluate(
    (element, [measured, reach]) => {
      type View = { pixelRaySegments(): { from: Point; to: Point }[]; probes: ViewProbes };
      const view = (element as unknown as { labView: View }).labView;
      const { width, height, mask } = view.probes.rayCoverage();
      const covered = (x: number, y: number) => x >= 0 && y >= 0 && x < width && y < height && mask[Math.round(y) * width + Math.round(x)] === 1;
      return view.pixelRaySegments().map(({ from, to }) => {
        const length = Math.hypot(to.x - from.x, to.y - from.y);
        if (length < measured) return null;
        const across = { x: -(to.y - from.y) / length, y: (to.x - from.x) / length };
        // Across the ray at a few places along it (an arrowhead, a crossing ray or an object may be at one of them): the narrowest seen.
        const seen = [0.2, 0.35, 0.7, 0.85].map((t) => {
          const at = { x: from.x + (to.x - from.x) * t, y: from.y + (to.y - from.y) * t };
          let count = 0;
          for (let s = -reach; s <= reach; s += 1) if (covered(at.x + across.x * s, at.y + across.y * s)) count++;
          return count;
        });
        return { from, to, seen };
      });
    },
    [MEASURED_LENGTH, 10] as const,
  );
  for (const ray of widths) {
    if (!ray) continue;
    const widest = Math.max(...ray.seen);
    expect(
      widest,
      `${where}: the ray ${JSON.stringify(ray.from)}→${JSON.stringify(ray.to)} is drawn at least ${RAY_MIN_WIDTH} px wide (seen ${ray.seen})`,
    ).toBeGreaterThanOrEqual(RAY_MIN_WIDTH);
  }
}
