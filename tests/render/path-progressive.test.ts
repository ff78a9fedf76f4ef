import { afterAll, describe, expect, it } from 'vitest';
import { createNodeRenderPool } from '../../src/cli/node-worker-port.ts';
import { MAX_PROGRESSIVE_PIXELS, pathPasses } from '../../src/render/path-passes.ts';
import type { FinishedRender, PathCount, RenderResult } from '../../src/render/render-job.ts';
import { planPasses } from '../../src/render/render-passes.ts';
import { TiledRender } from '../../src/render/tiled-render.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderPathTile } from '../../src/tracer/render-path-tile.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { cornellRoom } from '../support/cornell-room.ts';

const NO_MESHES = new Map();

function finished(result: RenderResult): FinishedRender {
  if (result.cancelled) throw new Error('the render was cancelled');
  return result;
}

const bits = (rgb: Float32Array) => new Uint8Array(rgb.buffer, rgb.byteOffset, rgb.byteLength);

describe("path mode's progressive passes", () => {
  it('follow the previews with one path per pixel per pass, paths 0 … N − 1 in order, each a final pass', () => {
    // 320 × 240 of the room: a pass of one path is estimated well over the shortest pass.
    const scene = cornellRoom({ pathSamples: 5 });
    const passes = planPasses(scene, { width: 320, height: 240, workers: 2, preview: true });
    const paths = passes.filter((pass) => pass.firstPath !== undefined);
    expect(passes.slice(0, passes.length - paths.length).every((pass) => pass.kind === 'preview')).toBe(true);
    expect(paths.map(({ kind, block, firstPath, samplesPerPixel }) => [kind, block, firstPath, samplesPerPixel])).toEqual(
      [0, 1, 2, 3, 4].map((first) => ['final', 1, first, 1]),
    );
  });

  it('add several paths a pass to a small image, and never make more than 256 passes', () => {
    const small = planPasses(cornellRoom({ pathSamples: 64 }), { width: 32, height: 24, workers: 2, preview: true });
    const counts = small.filter((pass) => pass.firstPath !== undefined).map((pass) => pass.samplesPerPixel);
    expect(counts.length).toBeGreaterThan(1);
    expect(counts[0]).toBeGreaterThan(1);
    expect(counts.reduce((sum, n) => sum + n, 0)).toBe(64);
    const many = planPasses(cornellRoom({ pathSamples: 65536 }), { width: 320, height: 240, workers: 2, preview: true });
    expect(many.filter((pass) => pass.firstPath !== undefined)).toHaveLength(256);
  });

  it('are left out without previews (rt render) and for an image over the sums the pool keeps', () => {
    const scene = cornellRoom({ pathSamples: 16 });
    const oneShot = planPasses(scene, { width: 320, height: 240, workers: 2, preview: false });
    expect(oneShot.map(({ kind, samplesPerPixel, firstPath }) => [kind, samplesPerPixel, firstPath])).toEqual([['final', 16, undefined]]);
    const huge = planPasses(scene, { width: 4096, height: MAX_PROGRESSIVE_PIXELS / 4096 + 1, workers: 2, preview: true });
    expect(huge.slice(-2).map(({ kind, samplesPerPixel, firstPath }) => [kind, samplesPerPixel, firstPath])).toEqual([
      ['sharp', 1, undefined],
      ['final', 16, undefined],
    ]);
  });

  it('end on the one-pass picture to the bit, passes of 1, 2 and 3 paths alike, and report the paths done', () => {
    const scene = cornellRoom({ pathSamples: 7 });
    const tracer = buildTracerScene(scene, NO_MESHES);
    const [width, height] = [13, 11];
    const whole = { x: 0, y: 0, width, height };
    const oneShot = renderTile(tracer, whole, { imageWidth: width, imageHeight: height, seed: 3 });
    for (const perPass of [1, 2, 3]) {
      const counts: PathCount[] = [];
      const tiles = new TiledRender(
        width,
        height,
        pathPasses(7, perPass, () => 5),
        { onProgress: ({ paths }) => paths && counts.push(paths) },
      );
      while (!tiles.finished) {
        for (let next = tiles.takeTile(); next; next = tiles.takeTile()) {
          const options = {
            imageWidth: width,
            imageHeight: height,
            seed: 3,
            samplesPerPixel: next.samplesPerPixel,
            firstPath: next.firstPath,
            pathSums: tiles.sumsOf(next.tile),
          };
          tiles.accept(next.tileId, renderPathTile(tracer, next.tile, options), emptyRayStats(), 1);
        }
      }
      expect(bits(tiles.image.rgb)).toEqual(bits(oneShot));
      const steps = Array.from({ length: Math.ceil(7 / perPass) }, (_, i) => Math.min(7, (i + 1) * perPass));
      expect([...new Set(counts.map((count) => count.done))]).toEqual([0, ...steps]);
      expect(counts.at(-1)).toEqual({ done: 7, total: 7, fraction: 1 });
    }
  });

  it('refuse a tile of 32-bit pixels in a path pass', () => {
    const tiles = new TiledRender(
      4,
      4,
      pathPasses(2, 1, () => 4),
      {},
    );
    const next = tiles.takeTile()!;
    expect(tiles.problemWith(next.tileId, new Float32Array(48))).toMatch(/pixels instead of sums of paths/);
    expect(tiles.problemWith(next.tileId, new Float64Array(48))).toBeNull();
  });
});

describe('a progressive path render in the worker pool', () => {
  const pool = createNodeRenderPool(2);
  afterAll(() => pool.dispose());
  // Russian roulette ends most paths early, while the estimate counts every path at full
  // length: passes of one path each, in a test that takes seconds.
  const scene = cornellRoom({ pathSamples: 3, maxDepth: 10, russianRoulette: true });
  const [width, height] = [160, 120];

  it('refines pass after pass, shows the paths so far, and ends on the picture rt render makes, to the bit', async () => {
    const done: number[] = [];
    const fractions: number[] = [];
    const progressive = finished(
      await pool.render(scene, NO_MESHES, {
        width,
        height,
        seed: 5,
        onProgress: ({ paths }) => {
          if (!paths) return;
          done.push(paths.done);
          fractions.push(paths.fraction);
        },
      }).done,
    );
    const oneShot = finished(await pool.render(scene, NO_MESHES, { width, height, seed: 5, preview: false }).done);
    expect(bits(progressive.rgb)).toEqual(bits(oneShot.rgb));
    expect(progressive.stats).toEqual(oneShot.stats);
    expect([...new Set(done)]).toEqual([0, 1, 2, 3]);
    expect(fractions).toEqual([...fractions].sort((a, b) => a - b));
    expect(fractions.at(-1)).toBe(1);
  });

  it('stops when cancelled, with the paths so far on show', async () => {
    let cancel = () => {};
    let shown = 0;
    const job = pool.render(scene, NO_MESHES, {
      width,
      height,
      onProgress: ({ paths }) => {
        if (paths && paths.done >= 1) {
          shown = paths.done;
          cancel();
        }
      },
    });
    cancel = () => job.cancel();
    expect((await job.done).cancelled).toBe(true);
    expect(shown).toBeGreaterThanOrEqual(1);
    expect(shown).toBeLessThan(3);
    // Every pixel holds the mean of its first paths: none is black in this closed, lit room.
    expect(job.image.rgb.some((value) => value > 0)).toBe(true);
  });
});
