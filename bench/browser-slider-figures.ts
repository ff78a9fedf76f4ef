import { existsSync, readFileSync } from 'node:fs';

/**
 * Slider to rays in the browser, as the last browser test run measured it
 * (e2e/slider-latency.spec.ts writes test-results/slider-latency.json, on SwiftShader):
 * the benchmark reports it beside its own Node figures, which leave out the panels and the
 * GPU's frame. The browser is not started here: the figure is as old as that run, and says so.
 */

const FIGURES_FILE = new URL('../test-results/slider-latency.json', import.meta.url);

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

/** The last browser run's figures, or null when there is none (or it cannot be read). */
export function browserSliderFigures(): BrowserSliderFigures | null {
  if (!existsSync(FIGURES_FILE)) return null;
  try {
    const figures = JSON.parse(readFileSync(FIGURES_FILE, 'utf8')) as BrowserSliderFigures;
    return figures.drag && figures.keys && figures.firstDrag ? figures : null;
  } catch {
    return null;
  }
}

export function browserSliderRows(figures: BrowserSliderFigures | null): [string, string, string][] {
  if (!figures) return [['slider to rays in the browser (e2e, SwiftShader)', 'not measured: run npx playwright test e2e/slider-latency.spec.ts', '≤ 100 ms p95']];
  const row = (name: string, latency: Latency): [string, string, string] => [
    `slider to rays in the browser, ${name} (e2e ${figures.measured.slice(0, 10)}, SwiftShader)`,
    `p50 ${latency.p50Ms} / p95 ${latency.p95Ms} / max ${latency.maxMs} ms${latency.lastDrawn ? '' : ', last value NOT drawn'}`,
    '≤ 100 ms p95',
  ];
  return [row('first drag', figures.firstDrag), row('drag', figures.drag), row('arrow keys', figures.keys)];
}
