/**
 * Writes the table of docs/benchmarks.md from bench/results.json (what `npm run bench` last
 * measured), between the page's two marker comments, so the page never shows figures the
 * benchmark no longer gives. Run after a benchmark: `npx tsx scripts/benchmark-table.ts`.
 * tests/scripts/benchmark-table.test.ts fails when the page and results.json disagree.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

export const TABLE_START = '<!-- benchmark-table:start (written by scripts/benchmark-table.ts from bench/results.json) -->';
export const TABLE_END = '<!-- benchmark-table:end -->';

export const RESULTS_PATH = fileURLToPath(new URL('../bench/results.json', import.meta.url));
export const PAGE_PATH = fileURLToPath(new URL('../docs/benchmarks.md', import.meta.url));

/** The parts of bench/results.json the table reads (run-bench.ts writes them). */
interface BenchResults {
  date: string;
  machine: { cores: number; node: string };
  referenceMs: Record<'1' | '2', number>;
  rays: { primary: number; shadow: number; reflect: number; refract: number };
  shadowRayShare: number;
  raysPerSecond: number;
  workerScaling: number;
  speedupVsNaive: number;
  naiveCrop: { width: number; height: number };
  primaryRayCasts: { oursNsPerRay: number; rawBvhRaycastFirstNsPerRay: number };
  firstPreviewMs: number;
  bvhBuildMs: number;
  slowestTileMs: number;
  anchor: { measured: string; anchorRenderMs2Threads: number; oursRenderMs2Workers: number; ratio: number };
  cyclesAnchor: { measured: string; pairs: number; cyclesRenderMs2Threads: number; oursRenderMs2Workers: number; ratio: number; rouletteRatio: number };
  objectCount: { ms: Record<'9' | '256', number>; ratio: number };
  rtRender16Ms: { introduction: number; reference: number };
  view: { drawCalls: Record<string, number>; rebuildMs: Record<string, number>; pick50kMs: number; screenTrace16x16Ms: number };
  firstLoad: { kB: { en: number; nl: number }; budgetKB: number; viewKB: number };
  sliderToRays: Record<'drag' | 'keys', { p50Ms: number; p95Ms: number }>;
}

const count = (n: number) => n.toLocaleString('en-US');

/** [measure, value, goal] rows, in the order and with the goals of the bench's own printed table. */
export function benchmarkRows(r: BenchResults): [string, string, string][] {
  return [
    ['reference render, 1 worker', `${r.referenceMs['1']} ms`, ''],
    ['reference render, 2 workers', `**${r.referenceMs['2']} ms**`, '≤ 1500 ms on a quiet machine'],
    [
      `vs the native Embree anchor, side by side (${r.anchor.measured})`,
      `${r.anchor.ratio}× (${r.anchor.oursRenderMs2Workers} / ${r.anchor.anchorRenderMs2Threads} ms)`,
      '≤ 2.0× (aim 1.5×)',
    ],
    [
      `path mode vs Blender's Cycles, Cornell box, side by side (${r.cyclesAnchor.measured})`,
      `${r.cyclesAnchor.ratio.toFixed(2)}×, median of ${r.cyclesAnchor.pairs} pairs (${r.cyclesAnchor.oursRenderMs2Workers} / ${r.cyclesAnchor.cyclesRenderMs2Threads} ms); ${r.cyclesAnchor.rouletteRatio.toFixed(2)}× with roulette, as Cycles`,
      '≤ 2.0× (aim 1.5×)',
    ],
    ['worker scaling 1 → 2', `${r.workerScaling}×`, '≥ 1.8×'],
    [
      'rays: primary / shadow / reflect / refract',
      `${count(r.rays.primary)} / ${count(r.rays.shadow)} / ${count(r.rays.reflect)} / ${count(r.rays.refract)}`,
      '',
    ],
    ['shadow rays', `${(r.shadowRayShare * 100).toFixed(1)} % of all rays`, ''],
    ['rays per second, 2 workers', `${(r.raysPerSecond / 1e6).toFixed(1)} M`, ''],
    [`vs a naive three.js Raycaster tracer, same shading (${r.naiveCrop.width}×${r.naiveCrop.height} crop)`, `**${r.speedupVsNaive}×** faster`, '≥ 10×'],
    [
      'primary ray nearest hit: ours / raw three-mesh-bvh `raycastFirst`',
      `${r.primaryRayCasts.oursNsPerRay} / ${r.primaryRayCasts.rawBvhRaycastFirstNsPerRay} ns`,
      '',
    ],
    ['first preview after an edit (warm workers, new scene)', `${r.firstPreviewMs} ms`, '≤ 250 ms'],
    ["BVH build of the scene's models", `${r.bvhBuildMs} ms`, ''],
    ['slowest tile of a render (bounds how fast a new render takes over)', `${r.slowestTileMs} ms`, '< 50 ms'],
    ['9 / 256 objects, 2 workers (grid scenes, 512 × 512)', `${r.objectCount.ms['9']} / ${r.objectCount.ms['256']} ms`, ''],
    ['cost of 256 objects vs 9', `${r.objectCount.ratio}×`, '≤ 1.3×'],
    ['`rt render` 16×16, whole command: level 1 / reference', `${r.rtRender16Ms.introduction} / ${r.rtRender16Ms.reference} ms`, '≤ 500 ms'],
    ['ray draw calls at 1k / 10k / 50k rays', `${r.view.drawCalls['1000']} / ${r.view.drawCalls['10000']} / ${r.view.drawCalls['50000']}`, 'constant'],
    ['ray pool rebuild after an option change, 10k / 50k rays', `${r.view.rebuildMs['10000']} / ${r.view.rebuildMs['50000']} ms`, '≤ 2 ms (10k)'],
    ['ray hover pick over 50k rays', `${r.view.pick50kMs} ms`, '< a frame'],
    ["the camera's 16×16 screen traced", `${r.view.screenTrace16x16Ms} ms`, ''],
    [
      'slider to rays, Node, drag / arrow keys: p50 / p95',
      `${r.sliderToRays.drag.p50Ms} / ${r.sliderToRays.drag.p95Ms} ms, ${r.sliderToRays.keys.p50Ms} / ${r.sliderToRays.keys.p95Ms} ms`,
      '≤ 100 ms p95',
    ],
    ['first load, gzipped JavaScript: English / Dutch', `${r.firstLoad.kB.en} / ${r.firstLoad.kB.nl} kB`, `≤ ${r.firstLoad.budgetKB} kB`],
    ['the 3D view, loaded after the first screen', `${r.firstLoad.viewKB} kB`, ''],
  ];
}

/** The Markdown table with the date and machine it was measured on. */
export function benchmarkTable(r: BenchResults): string {
  const lines = [
    `Measured ${r.date.slice(0, 10)} on ${r.machine.cores} cores, Node ${r.machine.node.replace(/^v/, '')}.`,
    '',
    '| measure | value | goal |',
    '| --- | --- | --- |',
    ...benchmarkRows(r).map((row) => `| ${row.join(' | ')} |`),
  ];
  return lines.join('\n');
}

/** `page` with the text between its markers replaced by the table of `results`. */
export function withBenchmarkTable(page: string, results: BenchResults): string {
  const start = page.indexOf(TABLE_START);
  const end = page.indexOf(TABLE_END);
  if (start < 0 || end < start) throw new Error(`docs/benchmarks.md has no "${TABLE_START}" … "${TABLE_END}" markers`);
  return `${page.slice(0, start + TABLE_START.length)}\n${benchmarkTable(results)}\n${page.slice(end)}`;
}

export function readResults(): BenchResults {
  return JSON.parse(readFileSync(RESULTS_PATH, 'utf8')) as BenchResults;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  writeFileSync(PAGE_PATH, withBenchmarkTable(readFileSync(PAGE_PATH, 'utf8'), readResults()));
  console.log(`wrote the table of ${PAGE_PATH}`);
}
