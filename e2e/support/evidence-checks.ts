import { expect, type Page } from '@playwright/test';
import type { TaskEvidence } from '../../src/quest/task-evidence-schema.ts';
import type { RayColorKey } from '../../src/view/ray-palette.ts';
import type { ViewProbes } from '../../src/view/view-probes.ts';

/**
 * Checks of a task's evidence at its start view (docs/levels.md, "Evidence"; issue 37):
 * every object and light the text names has its middle on the canvas and under no panel, and
 * what of it is on the canvas is large enough (a 3 m mirror framed close to the bounces it
 * holds may reach past the edge); every ray it names shows over at least RAY_MIN_LENGTH px of its length, counting
 * only what is on the canvas, hidden by no opaque object and under no panel (the pixel
 * preview, the legend, the view's buttons, the render window, a toast). The rays are the
 * named pixel's whether it is chosen yet or not: a task that asks the learner to choose it
 * is judged by the view the learner chooses it in. The 3D view is reached through
 * rt-scene-view's declared `labView` and its test probes (`labView.probes.evidenceRay`,
 * `labView.probes.projectedPointsOf`).
 */

/**
 * The least length of a named ray that must show, by the legend entry it is drawn as (CSS px):
 * about three arrowheads long, so that its direction, its colour and its dashes can be told.
 * A blocked shadow ray is short by nature (from a floor point to the ball just above it) and
 * shows a stop plate at its end: two arrowheads long is enough to read it.
 */
export const RAY_MIN_LENGTH: Readonly<Record<RayColorKey, number>> = {
  primary: 40,
  light: 40,
  shadow: 30,
  untested: 40,
  reflect: 40,
  refract: 40,
  'no-hit': 40,
  normal: 40,
};

/** The least size of a named object or light on screen: the shorter side of the box around it, within the canvas (CSS px). */
export const OBJECT_MIN_SIZE = 24;

type Point = { x: number; y: number };
interface InspectedView {
  canvas: HTMLCanvasElement;
  probes: Pick<ViewProbes, 'evidenceRay' | 'projectedPointsOf'>;
}

/** What was measured: each ray's length that shows, each object's size. */
export interface EvidenceFigures {
  rays: { path: string; drawnAs: RayColorKey | null; shown: number }[];
  objects: { id: string; size: number; uncovered: boolean }[];
}

/**
 * After the task's view has settled: what `evidence` names shows (see above). Soft checks:
 * every task's figures are measured (and returned) even when one falls short.
 */
export async function expectEvidenceShows(page: Page, where: string, evidence: TaskEvidence): Promise<EvidenceFigures> {
  // The pointer off the view: a ray's tooltip is no panel of the task's view.
  await page.mouse.move(2, 2);
  const sceneView = page.locator('rt-scene-view');
  if (evidence.rays) {
    const { pixel, paths } = evidence.rays;
    await expect
      .poll(
        () =>
          sceneView.evaluate((element, [at, path]) => (element as unknown as { labView: InspectedView }).labView.probes.evidenceRay(at, path) !== null, [
            pixel,
            paths[0]!,
          ] as const),
        {
          message: `${where}: pixel ${pixel}'s rays are traced`,
        },
      )
      .toBe(true);
  }
  const seen: EvidenceFigures = await sceneView.evaluate((element, named) => {
    const view = (element as unknown as { labView: InspectedView }).labView;
    const box = view.canvas.getBoundingClientRect();
    // What the pointer would be over at a point of the canvas, through every shadow root: the canvas itself, or a panel over it.
    const onCanvas = ({ x, y }: Point) => {
      if (x < 0 || y < 0 || x > box.width || y > box.height) return false;
      let over = document.elementFromPoint(box.left + x, box.top + y);
      while (over?.shadowRoot) {
        const inner = over.shadowRoot.elementFromPoint(box.left + x, box.top + y);
        if (!inner || inner === over) break;
        over = inner;
      }
      return over === view.canvas;
    };
    const rays = (named.rays?.paths ?? []).map((path) => {
      const ray = view.probes.evidenceRay(named.rays!.pixel, path);
      if (!ray) return { path, drawnAs: null, shown: 0 };
      let shown = 0;
      ray.points.forEach((point, index) => {
        const before = ray.points[index - 1];
        const visible = (p: Point & { hidden: boolean }) => !p.hidden && onCanvas(p);
        if (before && visible(before) && visible(point)) shown += Math.hypot(point.x - before.x, point.y - before.y);
      });
      return { path, drawnAs: ray.drawnAs, shown: Math.round(shown) };
    });
    const objects = (named.objects ?? []).map((id) => {
      const points = view.probes.projectedPointsOf(id);
      const placed = points.filter((point): point is Point => point !== null);
      const xs = placed.map((point) => point.x);
      const ys = placed.map((point) => point.y);
      const centre = { x: xs.reduce((sum, x) => sum + x, 0) / xs.length, y: ys.reduce((sum, y) => sum + y, 0) / ys.length };
      const within = (low: number, high: number, size: number) => Math.max(0, Math.min(high, size) - Math.max(low, 0));
      const size = Math.min(within(Math.min(...xs), Math.max(...xs), box.width), within(Math.min(...ys), Math.max(...ys), box.height));
      return { id, size: Math.round(size), uncovered: placed.length > 0 && onCanvas(centre) };
    });
    return { rays, objects };
  }, evidence);
  for (const ray of seen.rays) {
    expect.soft(ray.drawnAs, `${where}: pixel ${evidence.rays!.pixel} has a ray "${ray.path}"`).not.toBeNull();
    const least = RAY_MIN_LENGTH[ray.drawnAs!];
    expect
      .soft(
        ray.shown,
        `${where}: the ${ray.drawnAs} ray "${ray.path}" of pixel ${evidence.rays!.pixel} shows over at least ${least} px, on screen and under no panel`,
      )
      .toBeGreaterThanOrEqual(least);
  }
  for (const object of seen.objects) {
    expect.soft(object.uncovered, `${where}: the middle of "${object.id}" is on the 3D view, under no panel`).toBe(true);
    expect.soft(object.size, `${where}: "${object.id}" is at least ${OBJECT_MIN_SIZE} px across on the 3D view`).toBeGreaterThanOrEqual(OBJECT_MIN_SIZE);
  }
  return seen;
}
