import { describe, expect, it } from 'vitest';
import { createRenderHandler } from '../../workers/render-core.ts';
import type { RenderRequest, RenderResponse } from '../../workers/protocol.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import type { RayNode } from '../../src/tracer/ray-tree.ts';
import { sceneFrom } from '../support/test-scene.ts';
import { middleSample } from '../../src/tracer/trace-within-budget.ts';

const scene = defaultScene();
const load = (sceneId: number, file = scene): RenderRequest => ({ type: 'load-scene', sceneId, scene: file, meshes: new Map() });
const tile = (jobId: number, tileId: number): RenderRequest => ({
  type: 'render-tile',
  jobId,
  tileId,
  tile: { x: tileId * 4, y: 0, width: 4, height: 2 },
  options: { imageWidth: 64, imageHeight: 48, seed: 0 },
});

/** The worker core with its responses collected; `settle(n)` waits for n responses and any stragglers. */
function worker() {
  const responses: RenderResponse[] = [];
  const transfers: ArrayBuffer[][] = [];
  const handle = createRenderHandler((response, transfer) => {
    responses.push(response);
    transfers.push(transfer);
  });
  const settle = async (count: number) => {
    while (responses.length < count) await new Promise((resolve) => setImmediate(resolve));
    await new Promise((resolve) => setTimeout(resolve, 10));
  };
  return { handle, responses, transfers, settle };
}

describe('the render worker core', () => {
  it('builds the scene, then renders queued tiles in order and transfers their pixels', async () => {
    const { handle, responses, transfers, settle } = worker();
    handle(load(1));
    handle(tile(5, 0));
    handle(tile(5, 1));
    await settle(3);

    expect(responses.map((r) => r.type)).toEqual(['scene-ready', 'tile-done', 'tile-done']);
    const done = responses.filter((r) => r.type === 'tile-done');
    expect(done.map((r) => [r.jobId, r.tileId, r.rgb.length])).toEqual([
      [5, 0, 24],
      [5, 1, 24],
    ]);
    expect(transfers[1]).toEqual([done[0].rgb.buffer]);
  });

  it('drops the queued tiles of a cancelled job', async () => {
    const { handle, responses, settle } = worker();
    handle(load(1));
    handle(tile(5, 0));
    handle(tile(5, 1));
    handle({ type: 'cancel', jobId: 5 });
    handle(tile(6, 0));
    await settle(2);

    expect(responses.filter((r) => r.type === 'tile-done').map((r) => r.jobId)).toEqual([6]);
  });

  it('answers a pixel trace before the tiles queued ahead of it', async () => {
    const { handle, responses, settle } = worker();
    handle(load(1));
    handle(tile(5, 0));
    handle({ type: 'trace-pixel', requestId: 9, x: 4, y: 3, seed: 0 });
    await settle(3);

    expect(responses.map((r) => r.type)).toEqual(['scene-ready', 'pixel-traced', 'tile-done']);
  });

  it('traces a block of the screen in one answer, the same trees as one pixel at a time, and refuses pixels off the screen', async () => {
    const { handle, responses, settle } = worker();
    const [columns, rows] = scene.camera.pixels;
    const first = columns + 2; // wraps onto the next row
    handle(load(1));
    handle({ type: 'trace-pixels', requestId: 7, first, count: columns, seed: 3 });
    for (let i = 0; i < columns; i++)
      handle({ type: 'trace-pixel', requestId: 10 + i, x: (first + i) % columns, y: Math.floor((first + i) / columns), seed: 3 });
    handle({ type: 'trace-pixels', requestId: 8, first: columns * rows - 1, count: 2, seed: 3 });
    await settle(2 + columns + 1);

    const [, block, ...rest] = responses;
    const singles = rest.slice(0, columns).map((r) => (r.type === 'pixel-traced' ? r.trace : null));
    expect(block).toEqual({ type: 'pixels-traced', requestId: 7, traces: singles });
    expect(rest.at(-1)).toEqual({
      type: 'error',
      failed: { type: 'trace-pixels', requestId: 8 },
      message: `pixels ${columns * rows - 1} to ${columns * rows} are not on the ${columns}×${rows} screen`,
    });
  });

  it('sends a block within its budget: the same colours, fewer rays, and how many each pixel had', async () => {
    const { handle, responses, settle } = worker();
    // 4 × 4 samples of 4 × 4 lens points: 256 camera rays a pixel.
    const heavy = sceneFrom({ ...scene, camera: { ...scene.camera, aperture: 0.2, lensSamples: 4 }, settings: { ...scene.settings, supersampling: 4 } });
    handle(load(1, heavy));
    handle({ type: 'trace-pixels', requestId: 7, first: 0, count: 4, seed: 0 });
    handle({ type: 'trace-pixels', requestId: 8, first: 0, count: 4, seed: 0, budget: { rays: 200, keepPixel: 2 } });
    await settle(3);
    const [full, thinned] = responses.slice(1).map((r) => (r.type === 'pixels-traced' ? r.traces : []));
    expect(thinned.map((trace) => trace.color)).toEqual(full.map((trace) => trace.color));
    expect(thinned[2]).toEqual(full[2]);
    const count = (nodes: RayNode[]): number => nodes.reduce((sum, node) => sum + 1 + count(node.children), 0);
    const sent = thinned.reduce((sum, trace) => sum + count(trace.rays), 0);
    expect(sent).toBeLessThan(full.reduce((sum, trace) => sum + count(trace.rays), 0) / 2);
    for (const i of [0, 1, 3]) expect(thinned[i].traced).toBe(count(full[i].rays));
  });

  it('traces a block from one sample per pixel when the budget says so, the chosen pixel whole, nothing counted', async () => {
    const { handle, responses, settle } = worker();
    const heavy = sceneFrom({ ...scene, camera: { ...scene.camera, aperture: 0.2, lensSamples: 4 }, settings: { ...scene.settings, supersampling: 4 } });
    handle(load(1, heavy));
    handle({ type: 'trace-pixels', requestId: 7, first: 4, count: 4, seed: 0 });
    // Pixel 6 of the screen is the block's third.
    handle({ type: 'trace-pixels', requestId: 8, first: 4, count: 4, seed: 0, budget: { rays: 200, keepPixel: 6, oneSample: true } });
    await settle(3);
    const [full, sampled] = responses.slice(1).map((r) => (r.type === 'pixels-traced' ? r.traces : []));
    expect(sampled[2]).toEqual(full[2]);
    for (const i of [0, 1, 3]) {
      expect(sampled[i].onlySample).toBe(middleSample(4));
      expect(sampled[i].traced).toBeUndefined();
      expect(sampled[i].color).toEqual(full[i].rays[middleSample(4)].color!.map(Math.fround));
    }
  });

  it('renders a queued tile with the scene that was current when it arrived', async () => {
    const { handle, responses, settle } = worker();
    const dark = sceneFrom({ ...scene, settings: { ...scene.settings, background: [0, 0, 0] } });
    handle(load(1));
    handle(tile(5, 0));
    handle(load(2, dark));
    handle(tile(6, 0));
    await settle(4); // two scene-ready, two tile-done

    const [first, second] = responses.filter((r) => r.type === 'tile-done');
    expect([...first.rgb.slice(0, 3)]).toEqual(scene.settings.background.map(Math.fround));
    expect([...second.rgb.slice(0, 3)]).toEqual([0, 0, 0]);
  });

  it('turns every failure into an error response and keeps working', async () => {
    const { handle, responses, settle } = worker();
    handle(tile(1, 0));
    handle(load(2, sceneFrom({ objects: [{ id: 'gem', shape: 'mesh', mesh: 'prism' }] })));
    handle({ type: 'trace-pixel', requestId: 3, x: 0, y: 0, seed: 0 });
    handle(tile(4, 0));
    handle(load(5));
    handle(tile(6, 0));
    await settle(6);

    expect(responses).toEqual([
      { type: 'error', failed: { type: 'load-scene', sceneId: 2 }, message: expect.stringMatching(/"prism" was not loaded/) },
      { type: 'error', failed: { type: 'trace-pixel', requestId: 3 }, message: expect.stringMatching(/"prism" was not loaded/) },
      { type: 'scene-ready', sceneId: 5, ms: expect.any(Number) },
      { type: 'error', failed: { type: 'render-tile', jobId: 1, tileId: 0 }, message: 'no scene has been loaded' },
      { type: 'error', failed: { type: 'render-tile', jobId: 4, tileId: 0 }, message: expect.stringMatching(/"prism" was not loaded/) },
      expect.objectContaining({ type: 'tile-done', jobId: 6 }),
    ]);
  });
});

describe('the render worker core in path mode', () => {
  it('answers trace-paths with the first paths and every path’s contribution, their mean the pixel', async () => {
    const pathScene = { ...scene, settings: { ...scene.settings, integrator: 'path' as const, pathSamples: 12 } };
    const { handle, responses, settle } = worker();
    handle(load(1, pathScene));
    handle({ type: 'trace-paths', requestId: 9, x: 3, y: 2, seed: 5, keep: 4 });
    await settle(2);

    const answer = responses[1];
    if (answer?.type !== 'paths-traced') throw new Error(`expected paths-traced, got ${answer?.type}`);
    expect(answer.requestId).toBe(9);
    expect(answer.paths.pixel).toEqual([3, 2]);
    expect(answer.paths.pathCount).toBe(12);
    expect(answer.paths.paths).toHaveLength(4);
    expect(answer.paths.contributions).toHaveLength(12);
    expect(answer.paths.paths[0]!.vertices[0]!.event).toBe('camera');
    const mean = [0, 1, 2].map((c) => Math.fround(answer.paths.contributions.reduce((sum, contribution) => sum + contribution[c]!, 0) / 12));
    expect(answer.paths.color).toEqual(mean);
  });
});
