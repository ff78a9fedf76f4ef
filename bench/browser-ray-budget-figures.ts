import { COMPOSITING, COMPOSITINGS, type Compositing, lastBrowserRun } from './browser-compositing.ts';

/**
 * The live view with the free lab's largest settings, as the last browser test run measured
 * it (e2e/ray-budget.spec.ts writes test-results/ray-budget-<project>.json, WebGL on
 * SwiftShader): supersampling 4, a 4 × 4 lens and 4 shutter times, 1,024 camera rays a
 * pixel, over 100,000 rays on the free lab's 8 × 6 screen (issue 38, item 6: a frame of them
 * took seconds, 8 slider steps 11–12 s). While the slider moves, the view draws a budget of
 * the rays (view/ray-budget.ts). A step is timed to the first frame that shows its value,
 * and to the first that shows rays traced with it (the worker traces the whole screen first).
 * `npm run bench` reports it beside its own figures; the browser is not started here, so the
 * figure is as old as that run, and says so. `npx tsx bench/browser-ray-budget-figures.ts`
 * prints these rows alone.
 */

interface Latency {
  steps: number;
  p50Ms: number;
  p95Ms: number;
  maxMs: number;
}

interface Moving {
  /** To the first frame that shows the step's value. */
  view: Latency;
  /** To the first frame that shows rays traced with it. */
  rays: Latency;
  /** The most rays a frame drew while the slider moved. */
  mostRays: number;
  /** From the last step to the frame with every ray, on screen. */
  allRaysAfterMs: number;
}

export interface BrowserRayBudgetFigures {
  measured: string;
  allRays: number;
  drag: Moving;
  keys: Moving & { wallMs: number };
}

/** Per way of compositing, the last browser run's figures, or null when there is none (or it cannot be read). */
export function browserRayBudgetFigures(): Record<Compositing, BrowserRayBudgetFigures | null> {
  return lastBrowserRun('ray-budget', (json) => {
    const figures = json as BrowserRayBudgetFigures;
    return figures.drag?.view && figures.keys?.view && typeof figures.allRays === 'number' ? figures : null;
  });
}

export function browserRayBudgetRows(all: Record<Compositing, BrowserRayBudgetFigures | null>): [string, string, string][] {
  return COMPOSITINGS.flatMap((compositing) => rowsOf(compositing, all[compositing]));
}

function rowsOf(compositing: Compositing, figures: BrowserRayBudgetFigures | null): [string, string, string][] {
  const how = COMPOSITING[compositing];
  if (!figures)
    return compositing === 'chromium'
      ? [[`live view, largest free-lab settings (e2e, ${how})`, 'not measured: run npx playwright test e2e/ray-budget.spec.ts', '≤ 100 ms p95']]
      : [];
  const when = `e2e ${figures.measured.slice(0, 10)}, ${how}`;
  const latency = ({ p50Ms, p95Ms, maxMs }: Latency) => `p50 ${p50Ms} / p95 ${p95Ms} / max ${maxMs} ms`;
  const rays = figures.allRays.toLocaleString('en');
  const { drag, keys } = figures;
  return [
    [`largest free-lab settings, ${rays} rays: drag, step to its frame (${drag.view.steps} steps, ${when})`, latency(drag.view), '≤ 100 ms p95'],
    [`  the same, step to its rays (traced in the worker)`, latency(drag.rays), ''],
    [
      `  arrow keys a step per 150 ms, step to its frame (${keys.view.steps} steps)`,
      `${latency(keys.view)}; ${(keys.wallMs / 1000).toFixed(1)} s in all`,
      '≤ 100 ms p95',
    ],
    [`  the same, step to its rays`, latency(keys.rays), ''],
    [
      `  rays a frame drew while the slider moved; all again after the last step`,
      `${Math.max(drag.mostRays, keys.mostRays).toLocaleString('en')}; ${(drag.allRaysAfterMs / 1000).toFixed(1)} / ${(keys.allRaysAfterMs / 1000).toFixed(1)} s`,
      '',
    ],
  ];
}

if (process.argv[1]?.endsWith('browser-ray-budget-figures.ts')) {
  const { printTable } = await import('./print-table.ts');
  printTable(browserRayBudgetRows(browserRayBudgetFigures()));
}
