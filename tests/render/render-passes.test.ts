import { describe, expect, it } from 'vitest';
import { RAYS_PER_SECOND_PER_WORKER, raysPerSample } from '../../src/render/render-estimate.ts';
import type { RenderProgress } from '../../src/render/render-job.ts';
import { FIRST_PASS_SECONDS, planPasses, tracedSamples, type RenderPass } from '../../src/render/render-passes.ts';
import { TiledRender, type TileAssignment } from '../../src/render/tiled-render.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { Scene } from '../../src/scene/scene.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { heaviestScene } from '../support/heavy-scenes.ts';
import { sceneFrom } from '../support/test-scene.ts';

function withSupersampling(supersampling: number): Scene {
  return sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, supersampling } });
}

/** The render estimate's seconds for one pass of a width × height image on `workers` workers. */
function passSeconds(scene: Scene, pass: RenderPass, width: number, height: number, workers: number): number {
  return (tracedSamples({ x: 0, y: 0, width, height }, pass) * raysPerSample(scene)) / (RAYS_PER_SECOND_PER_WORKER * workers);
}

/** Runs a whole render through TiledRender with blank tiles, recording every progress report. */
function playRender(width: number, height: number, passes: RenderPass[]): { reports: RenderProgress[]; previews: number } {
  const reports: RenderProgress[] = [];
  let previews = 0;
  const tiles = new TiledRender(width, height, passes, { onProgress: (report) => reports.push(report), onPreview: () => previews++ });
  while (!tiles.finished) {
    const taken = [];
    for (let next = tiles.takeTile(); next; next = tiles.takeTile()) taken.push(next);
    // One ray per sample: the progress in rays counts the pass's samples.
    for (const { tileId, tile, block, samplesPerPixel } of taken) {
      tiles.accept(tileId, new Float32Array(tile.width * tile.height * 3), { ...emptyRayStats(), primary: tracedSamples(tile, { block, samplesPerPixel }) }, 1);
    }
  }
  return { reports, previews };
}

describe('the pass plan', () => {
  it("traces path mode's N paths per pixel in one final pass without previews (rt render; the window's passes: path-progressive.test.ts)", () => {
    const scene = sceneFrom({ ...defaultScene(), settings: { ...defaultScene().settings, integrator: 'path', pathSamples: 10 } });
    const passes = planPasses(scene, { width: 64, height: 48, workers: 2, preview: false });
    expect(passes.map(({ kind, samplesPerPixel }) => [kind, samplesPerPixel])).toEqual([['final', 10]]);
    const stats = emptyRayStats();
    const tile = { x: 0, y: 0, width: 4, height: 3 };
    renderTile(buildTracerScene(scene, new Map()), tile, { imageWidth: 64, imageHeight: 48, seed: 0, samplesPerPixel: passes.at(-1)!.samplesPerPixel }, stats);
    expect(stats.primary).toBe(10 * 4 * 3);
  });

  it('previews the default scene in 8×8 and 4×4 blocks, then a sharp one-sample pass, then full quality', () => {
    const passes = planPasses(withSupersampling(2), { width: 512, height: 384, workers: 2, preview: true });
    expect(passes.map(({ kind, block, samplesPerPixel }) => [kind, block, samplesPerPixel])).toEqual([
      ['preview', 8, 1],
      ['preview', 4, 1],
      ['sharp', 1, 1],
      ['final', 1, 4],
    ]);
    // The sharp pass costs a quarter of the final one with 2×2 supersampling.
    const [sharp, final] = passes.slice(2).map((pass) => tracedSamples({ x: 0, y: 0, width: 512, height: 384 }, pass));
    expect(sharp * 4).toBe(final);
  });

  it('previews in whole rows of blocks, each tile tracing as many samples as a sharp-pass tile', () => {
    const scene = withSupersampling(2);
    const passes = planPasses(scene, { width: 512, height: 384, workers: 2, preview: true });
    const sharp = passes.find((pass) => pass.kind === 'sharp')!;
    const sharpTile = tracedSamples({ x: 0, y: 0, width: sharp.tileWidth, height: sharp.tileHeight }, sharp);
    for (const pass of passes.filter((p) => p.kind === 'preview')) {
      expect(pass.tileWidth).toBeGreaterThanOrEqual(512);
      expect(tracedSamples({ x: 0, y: 0, width: pass.tileWidth, height: pass.tileHeight }, pass)).toBe(sharpTile);
    }
  });

  it('leaves out the sharp pass when the final pass already traces one sample per pixel', () => {
    const kinds = planPasses(withSupersampling(1), { width: 512, height: 384, workers: 2, preview: true }).map((pass) => pass.kind);
    expect(kinds).toEqual(['preview', 'preview', 'final']);
  });

  it('makes only the final pass without previews (rt render)', () => {
    expect(planPasses(withSupersampling(3), { width: 64, height: 64, workers: 1, preview: false })).toEqual([
      { kind: 'final', block: 1, samplesPerPixel: 9, tileWidth: expect.any(Number), tileHeight: expect.any(Number) },
    ]);
  });

  it('gives a render without previews (rt render) final tiles of 24 times the rays: √24 times the side, up to 32', () => {
    const finalSide = (supersampling: number, preview: boolean) =>
      planPasses(withSupersampling(supersampling), { width: 512, height: 384, workers: 2, preview }).at(-1)!.tileWidth;
    for (const supersampling of [3, 4, 6, 8]) {
      // The watched side is floor(√(rays per tile / rays per pixel)), so that root lies in [watched, watched + 1).
      const watched = finalSide(supersampling, true);
      const unwatched = finalSide(supersampling, false);
      expect(unwatched, `supersampling ${supersampling}`).toBeGreaterThanOrEqual(Math.min(32, Math.floor(Math.sqrt(24) * watched)));
      expect(unwatched, `supersampling ${supersampling}`).toBeLessThan(Math.min(33, Math.sqrt(24) * (watched + 1)));
    }
    expect(finalSide(2, false)).toBe(32);
  });

  it('starts the heaviest scene with a pass the estimate puts under the first second, halving the block down to 4', () => {
    const [width, height] = heaviestScene.settings.imageSize;
    const passes = planPasses(heaviestScene, { width, height, workers: 2, preview: true });
    const previews = passes.filter((pass) => pass.kind === 'preview');
    expect(passSeconds(heaviestScene, previews[0], width, height, 2)).toBeLessThanOrEqual(FIRST_PASS_SECONDS);
    // The finest block that fits: twice as fine would not.
    expect(passSeconds(heaviestScene, { ...previews[0], block: previews[0].block / 2 }, width, height, 2)).toBeGreaterThan(FIRST_PASS_SECONDS);
    expect(previews.map((pass) => pass.block)).toEqual(previews.map((_, i) => previews[0].block / 2 ** i));
    expect(previews.at(-1)?.block).toBe(4);
    expect(passes.slice(previews.length).map((pass) => pass.kind)).toEqual(['sharp', 'final']);
    for (const pass of passes) expect([pass.tileWidth % pass.block, pass.tileHeight % pass.block]).toEqual([0, 0]);
  });
});

describe('render progress', () => {
  it('reports each pass from its first tile to its last, and previews after every pass but the last', () => {
    const [width, height] = [300, 225]; // several tiles per pass, partial ones at the edges
    const passes = planPasses(withSupersampling(2), { width, height, workers: 2, preview: true });
    const { reports, previews } = playRender(width, height, passes);

    expect(previews).toBe(passes.length - 1);
    for (const [index, pass] of passes.entries()) {
      const ofPass = reports.filter((report) => report.pass === index + 1);
      expect(ofPass.every((report) => report.phase === pass.kind && report.passes === passes.length)).toBe(true);
      // The first tile is reported at once (one tile's rays), the last always, at 100 %.
      expect(ofPass[0].done).toBe(tracedSamples({ x: 0, y: 0, width: Math.min(pass.tileWidth, width), height: Math.min(pass.tileHeight, height) }, pass));
      expect(ofPass.at(-1)?.done).toBe(ofPass.at(-1)?.total);
      expect(ofPass.at(-1)?.done).toBe(tracedSamples({ x: 0, y: 0, width, height }, pass));
    }
    expect(reports.map((report) => report.pass)).toEqual([...reports.map((report) => report.pass)].sort((a, b) => a - b));
  });

  it('gives the heaviest scene a first pass of a handful of one-sample tiles, each reported as a step', () => {
    const [width, height] = heaviestScene.settings.imageSize;
    const [first] = planPasses(heaviestScene, { width, height, workers: 2, preview: true });
    const tiles = new TiledRender(width, height, [first], {});
    const sizes = [];
    for (let next = tiles.takeTile(); next; next = tiles.takeTile()) sizes.push(tracedSamples(next.tile, next));
    expect(sizes.every((samples) => samples === 1)).toBe(true);
    expect(sizes.length).toBe(tracedSamples({ x: 0, y: 0, width, height }, first));
  });
});

describe('what a painter must redraw', () => {
  it('the tiles pasted into the image since it last asked, and none after', () => {
    const [pass] = planPasses(withSupersampling(1), { width: 100, height: 70, workers: 1, preview: false });
    const tiles = new TiledRender(100, 70, [pass], {});
    expect(tiles.takeChanges()).toBeNull();
    const taken: TileAssignment[] = [];
    for (let next = tiles.takeTile(); next; next = tiles.takeTile()) taken.push(next);
    const paste = ({ tileId, tile }: TileAssignment) => tiles.accept(tileId, new Float32Array(tile.width * tile.height * 3), emptyRayStats(), 1);
    const bottom = taken.filter(({ tile }) => tile.y + tile.height === 70);
    paste(bottom[0]);
    expect(tiles.takeChanges()).toEqual({ preview: null, tiles: [bottom[0].tile] });
    expect(tiles.takeChanges()).toBeNull();
    paste(taken[0]);
    paste(bottom[1]);
    expect(tiles.takeChanges()).toEqual({ preview: null, tiles: [taken[0].tile, bottom[1].tile] });
  });

  it('a preview pass at its own resolution, one value per block, and the image untouched until the sharp pass', () => {
    const [width, height, block] = [10, 7, 4];
    const preview: RenderPass = { kind: 'preview', block, samplesPerPixel: 1, tileWidth: 12, tileHeight: 4 };
    const sharp: RenderPass = { kind: 'sharp', block: 1, samplesPerPixel: 1, tileWidth: 5, tileHeight: 5 };
    const shown: unknown[] = [];
    const tiles = new TiledRender(width, height, [preview, sharp], { onPreview: (image) => shown.push(image) });
    // As a worker fills a preview tile: every pixel of a block has the block's value.
    const filled = ({ tile }: TileAssignment) => {
      const rgb = new Float32Array(tile.width * tile.height * 3);
      for (let y = 0; y < tile.height; y++) {
        for (let x = 0; x < tile.width; x++) rgb.set([tile.x + x - (x % block), tile.y + y - (y % block), 1], (y * tile.width + x) * 3);
      }
      return rgb;
    };
    const [top, lower] = [tiles.takeTile()!, tiles.takeTile()!];
    tiles.accept(lower.tileId, filled(lower), emptyRayStats(), 1);
    const changes = tiles.takeChanges()!;
    expect(changes.tiles).toEqual([]);
    expect(changes.preview?.rows).toEqual([1, 2]);
    const image = changes.preview!.image;
    expect([image.width, image.height, image.block]).toEqual([3, 2, block]);
    tiles.accept(top.tileId, filled(top), emptyRayStats(), 1);
    expect(tiles.takeChanges()?.preview?.rows).toEqual([0, 1]);
    // Block (i, j)'s value is its top-left pixel's: (4i, 4j).
    expect([...image.rgb]).toEqual([0, 0, 1, 4, 0, 1, 8, 0, 1, 0, 4, 1, 4, 4, 1, 8, 4, 1]);
    expect(shown).toEqual([image]);
    expect(tiles.image.rgb.every((value) => value === 0)).toBe(true);
    // The sharp pass pastes into the image, and is the one the painter hears of next.
    const first = tiles.takeTile()!;
    tiles.accept(first.tileId, new Float32Array(25 * 3).fill(0.5), emptyRayStats(), 1);
    expect(tiles.takeChanges()).toEqual({ preview: null, tiles: [first.tile] });
    expect(tiles.image.rgb[0]).toBe(0.5);
  });

  it('a finer preview starts as the coarser one scaled up, and takes over its rows not yet asked for', () => {
    const coarse: RenderPass = { kind: 'preview', block: 4, samplesPerPixel: 1, tileWidth: 8, tileHeight: 8 };
    const fine: RenderPass = { ...coarse, block: 2 };
    const tiles = new TiledRender(8, 8, [coarse, fine], {});
    const only = tiles.takeTile()!;
    const rgb = new Float32Array(8 * 8 * 3).map((_, i) => (Math.floor(i / 3) % 8 < 4 ? 1 : 2)); // left blocks 1, right blocks 2
    tiles.accept(only.tileId, rgb, emptyRayStats(), 1);
    const changes = tiles.takeChanges()!;
    expect(changes.preview).toMatchObject({ rows: [0, 4] });
    expect(changes.preview?.image).toMatchObject({ width: 4, height: 4, block: 2 });
    expect([...changes.preview!.image.rgb.filter((_, i) => i % 3 === 0)]).toEqual([1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2]);
  });

  it('past 256 tiles, the rows they span as one full-width tile', () => {
    const pass: RenderPass = { kind: 'final', block: 1, samplesPerPixel: 1, tileWidth: 1, tileHeight: 1 };
    const tiles = new TiledRender(30, 20, [pass], {});
    for (let i = 0; i < 300; i++) {
      const next = tiles.takeTile()!;
      tiles.accept(next.tileId, new Float32Array(3), emptyRayStats(), 1);
    }
    // Tiles 0–299 cover rows 0–9 of the 30-pixel rows.
    expect(tiles.takeChanges()).toEqual({ preview: null, tiles: [{ x: 0, y: 0, width: 30, height: 10 }] });
  });
});
