import { COMPOSITING, COMPOSITINGS, type Compositing, lastBrowserRun } from './browser-compositing.ts';

/**
 * Slider to rays in the browser, as the last browser test run measured it
 * (e2e/slider-latency.spec.ts writes test-results/slider-latency-<project>.json, WebGL on
 * SwiftShader): the benchmark reports it beside its own Node figures, which leave out the
 * panels and the GPU's frame. The browser is not started here: the figure is as old as that
 * run, and says so. One file per way of compositing the page (browser-compositing.ts).
 */

interface Latency {
  steps: number;
  p50Ms: number;
  p95Ms: number;
  maxMs: number;
  lastDrawn: boolean;
}

export interface BrowserSliderFigures {
  measured: string;
  firstDrag: Latency;
  drag: Latency;
  keys: Latency;
}

/** Per way of compositing, the last browser run's figures, or null when there is none (or it cannot be read). */
export function browserSliderFigures(): Record<Compositing, BrowserSliderFigures | null> {
  return lastBrowserRun('slider-latency', (json) => {
    const figures = json as BrowserSliderFigures;
    return figures.drag && figures.keys && figures.firstDrag ? figures : null;
  });
}

export function browserSliderRows(all: Record<Compositing, BrowserSliderFigures | null>): [string, string, string][] {
  return COMPOSITINGS.flatMap((compositing) => rowsOf(compositing, all[compositing]));
}

function rowsOf(compositing: Compositing, figures: BrowserSliderFigures | null): [string, string, string][] {
  const how = COMPOSITING[compositing];
  if (!figures) return [[`slider to rays in the browser (e2e, ${how})`, 'not measured: run npx playwright test e2e/slider-latency.spec.ts', '≤ 100 ms p95']];
  const row = (name: string, latency: Latency): [string, string, string] => [
    `slider to rays in the browser, ${name} (e2e ${figures.measured.slice(0, 10)}, ${how})`,
    `p50 ${latency.p50Ms} / p95 ${latency.p95Ms} / max ${latency.maxMs} ms${latency.lastDrawn ? '' : ', last value NOT drawn'}`,
    '≤ 100 ms p95',
  ];
  return [row('first drag', figures.firstDrag), row('drag', figures.drag), row('arrow keys', figures.keys)];
}
