import { expect, test, type CDPSession, type Page } from '@playwright/test';
import { collectErrors, viewLoaded } from './support/game-steps.ts';

/**
 * The level map, opened 40 times from level 1 and closed again ("Back to the level"), as a
 * learner looks up where they are (issue 38, item 5). Each opening draws the lab's panels
 * behind the map and each return removes them; every visit used to keep the old panels alive
 * (about 2,000 DOM nodes, 222 listeners and 0.32 MB a visit, held by the lab's guide
 * registry: GuideRegistry). After visit 10 and after visit 40, with the garbage collected (CDP
 * HeapProfiler.collectGarbage), the page must be as large: the elements on it (shadow roots
 * included), the DOM nodes alive (Performance.getMetrics' Nodes: detached ones too), the
 * event listeners and the JavaScript heap, each within a tolerance far below one visit's leak.
 */

const VISITS = 40;
const MEASURED_AFTER = 10;

/**
 * Growth allowed over the last 30 visits. One visit used to add about 2,400 DOM nodes, 290
 * listeners and 316 KB; now the nodes and listeners stay exactly as they were, and the heap
 * grows by the progress log's events of each visit (0.7 kB of JSON a visit) and the JIT's
 * late work: 18 kB a visit over visits 10 to 40 on this project's machine, 7 kB a visit by
 * visit 80. The heap's tolerance, 50 kB a visit, is a sixth of the old leak.
 */
const TOLERANCE = { elements: 0, nodes: 600, listeners: 60, heapBytes: 1_500_000 };

interface Size {
  /** Elements on the page, inside shadow roots too. */
  elements: number;
  /** DOM nodes alive, attached or not. */
  nodes: number;
  listeners: number;
  heapBytes: number;
}

async function size(page: Page, cdp: CDPSession): Promise<Size> {
  // Twice: objects freed by the first collection can free more (weak maps, finalizers).
  await cdp.send('HeapProfiler.collectGarbage');
  await cdp.send('HeapProfiler.collectGarbage');
  const { metrics } = await cdp.send('Performance.getMetrics');
  const metric = (name: string) => metrics.find((entry) => entry.name === name)?.value ?? NaN;
  const elements = await page.evaluate(() => {
    const count = (root: Document | ShadowRoot): number =>
      [...root.querySelectorAll('*')].reduce((sum, element) => sum + 1 + (element.shadowRoot ? count(element.shadowRoot) : 0), 0);
    return count(document);
  });
  return { elements, nodes: metric('Nodes'), listeners: metric('JSEventListeners'), heapBytes: metric('JSHeapUsedSize') };
}

test('forty visits to the level map leave the page no larger than ten did', async ({ page }) => {
  test.slow();
  const errors = collectErrors(page);
  await page.goto('./');
  await page.getByRole('button', { name: 'Got it' }).click();
  await viewLoaded(page);
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');
  const map = page.locator('rt-level-map');
  const sizes: Size[] = [];
  for (let visit = 1; visit <= VISITS; visit++) {
    await page.locator('[data-command="levels"]').click();
    await expect(map.getByRole('button', { name: 'Back to the level' })).toBeVisible();
    await map.getByRole('button', { name: 'Back to the level' }).click();
    await expect(map).toHaveCount(0);
    if (visit === MEASURED_AFTER || visit === VISITS) sizes.push(await size(page, cdp));
  }
  const [after10, after40] = sizes;
  const growth = {
    elements: after40.elements - after10.elements,
    nodes: after40.nodes - after10.nodes,
    listeners: after40.listeners - after10.listeners,
    heapBytes: after40.heapBytes - after10.heapBytes,
  };
  test.info().annotations.push({ type: 'sizes', description: JSON.stringify({ after10, after40, growth }) });
  expect(growth.elements, 'elements on the page').toBeLessThanOrEqual(TOLERANCE.elements);
  expect(growth.nodes, 'DOM nodes alive').toBeLessThanOrEqual(TOLERANCE.nodes);
  expect(growth.listeners, 'event listeners').toBeLessThanOrEqual(TOLERANCE.listeners);
  expect(growth.heapBytes, 'JavaScript heap').toBeLessThanOrEqual(TOLERANCE.heapBytes);
  expect(errors).toEqual([]);
});
