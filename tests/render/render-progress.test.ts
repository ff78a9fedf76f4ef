import { afterEach, describe, expect, it, vi } from 'vitest';
import type { RenderProgress } from '../../src/render/render-job.ts';
import { planPasses, tracedSamples, type RenderPass } from '../../src/render/render-passes.ts';
import { RenderWork } from '../../src/render/render-work.ts';
import { TiledRender } from '../../src/render/tiled-render.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import type { Tile } from '../../src/tracer/tile.ts';
import { sceneFrom } from '../support/test-scene.ts';

const [WIDTH, HEIGHT] = [300, 225];

/**
 * Rays of one sample at pixel (x, y) of a scene whose dear part is a ball in the middle
 * (glass under an area light: 120 rays a sample) on a cheap background (2 rays).
 */
function raysAt(x: number, y: number): number {
  return Math.hypot(x - WIDTH / 2, y - HEIGHT / 2) < 60 ? 120 : 2;
}

/** The rays a tile of `pass` traces: one sample per block (at its top-left pixel), s² per pixel in the final pass. */
function tileRays(tile: Tile, { block, samplesPerPixel }: Pick<RenderPass, 'block' | 'samplesPerPixel'>): number {
  let rays = 0;
  for (let y = tile.y; y < tile.y + tile.height; y += block) {
    for (let x = tile.x; x < tile.x + tile.width; x += block) rays += raysAt(x, y) * samplesPerPixel;
  }
  return rays;
}

/** A whole render through TiledRender, its tiles back in order with the rays of raysAt; every progress report and each tile's rays. */
function playRender(passes: RenderPass[]): { reports: RenderProgress[]; tiles: { pass: number; rays: number; samples: number }[] } {
  const reports: RenderProgress[] = [];
  const returned: { pass: number; rays: number; samples: number }[] = [];
  // Every tile 100 ms after the last, so that each is reported (reports come at most every 50 ms).
  let clock = 0;
  vi.spyOn(performance, 'now').mockImplementation(() => (clock += 100));
  const render = new TiledRender(WIDTH, HEIGHT, passes, { onProgress: (report) => reports.push(report) }, 10);
  for (let pass = 1; !render.finished; pass++) {
    const taken = [];
    for (let next = render.takeTile(); next; next = render.takeTile()) taken.push(next);
    for (const assignment of taken) {
      const rays = tileRays(assignment.tile, assignment);
      returned.push({ pass, rays, samples: tracedSamples(assignment.tile, assignment) });
      render.accept(assignment.tileId, new Float32Array(assignment.tile.width * assignment.tile.height * 3), { ...emptyRayStats(), primary: rays }, 1);
    }
  }
  return { reports, tiles: returned };
}

const passes = planPasses(sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, supersampling: 2 } }), {
  width: WIDTH,
  height: HEIGHT,
  workers: 2,
  preview: true,
});

describe('the progress of a render, in rays', () => {
  afterEach(() => vi.restoreAllMocks());

  it('only rises in every pass, and reads 1 at its last tile and never before', () => {
    const { reports } = playRender(passes);
    for (let pass = 1; pass <= passes.length; pass++) {
      const fractions = reports.filter((report) => report.pass === pass).map(({ done, total }) => done / total);
      for (let i = 1; i < fractions.length; i++) expect(fractions[i], `pass ${pass}, report ${i}`).toBeGreaterThanOrEqual(fractions[i - 1]);
      expect(fractions.slice(0, -1).every((fraction) => fraction < 1)).toBe(true);
      expect(fractions.at(-1)).toBe(1);
    }
  });

  it('counts the rays the workers traced, so the last report of a pass is all its rays', () => {
    const { reports, tiles } = playRender(passes);
    for (let pass = 1; pass <= passes.length; pass++) {
      const last = reports.filter((report) => report.pass === pass).at(-1)!;
      const rays = tiles.filter((tile) => tile.pass === pass).reduce((sum, tile) => sum + tile.rays, 0);
      expect(last.done).toBe(rays);
      expect(last.total).toBe(rays);
    }
  });

  it('keeps pace with the rays in the full-quality pass, where counting samples would not', () => {
    const { reports, tiles } = playRender(passes);
    const final = passes.length;
    expect(reports.filter((r) => r.pass === final).length).toBe(tiles.filter((tile) => tile.pass === final).length);
    const ofFinal = tiles.filter((tile) => tile.pass === final);
    const allRays = ofFinal.reduce((sum, tile) => sum + tile.rays, 0);
    const allSamples = ofFinal.reduce((sum, tile) => sum + tile.samples, 0);
    // The share of rays and of samples after each tile: the true progress, and what a sample count would say.
    let [rays, samples] = [0, 0];
    const truth = new Map<number, number>();
    let worstSampleCount = 0;
    for (const tile of ofFinal) {
      [rays, samples] = [rays + tile.rays, samples + tile.samples];
      truth.set(rays, rays / allRays);
      worstSampleCount = Math.max(worstSampleCount, Math.abs(samples / allSamples - rays / allRays));
    }
    // The ball makes a sample count wrong by a fifth of the pass or more...
    expect(worstSampleCount).toBeGreaterThan(0.2);
    // ...while the rays predicted from the previews stay within 3 % of the truth.
    for (const report of reports.filter((r) => r.pass === final)) {
      expect(Math.abs(report.done / report.total - truth.get(report.done)!), `at ${report.done} rays`).toBeLessThan(0.03);
    }
  });

  it('gives a time left only in the final pass, which is most of the render', () => {
    const { reports } = playRender(passes);
    expect(reports.filter((report) => report.phase !== 'final').every((report) => report.secondsLeft === null)).toBe(true);
    expect(reports.filter((report) => report.phase === 'final').some((report) => report.secondsLeft !== null)).toBe(true);
  });

  it("gives the time left from the rays left at the rate since the final pass's first tile, after two seconds of it", () => {
    let now = 0;
    vi.spyOn(performance, 'now').mockImplementation(() => now);
    const [pass] = planPasses(defaultScene(), { width: 100, height: 100, workers: 1, preview: false });
    const work = new RenderWork(100, 100, [pass], 4);
    const tenth = (row: number) => ({ x: 0, y: row * 10, width: 100, height: 10 });
    const rays = { ...emptyRayStats(), primary: 4000 }; // 4 rays a sample, as assumed
    // The workers built the scene for 30 s: that says nothing of how fast they trace.
    now = 30_000;
    expect(work.tileBack(tenth(0), 1000, rays, false).secondsLeft).toBeNull();
    now = 31_000;
    expect(work.tileBack(tenth(1), 1000, rays, false).secondsLeft).toBeNull();
    // A tenth of the image a second since the first tile: 7 tenths left, 7 s.
    now = 32_000;
    const third = work.tileBack(tenth(2), 1000, rays, false);
    expect(third.done / third.total).toBeCloseTo(0.3);
    expect(third.secondsLeft).toBeCloseTo(7);
  });
});
