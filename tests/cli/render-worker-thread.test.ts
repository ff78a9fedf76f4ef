import { describe, expect, it, vi } from 'vitest';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { createNodeRenderPool, createNodeWorkerPort } from '../../src/cli/node-worker-port.ts';
import { prestartRenderWorker, takePrestartedRenderWorker } from '../../src/cli/render-worker-thread.ts';
import type { FinishedRender } from '../../src/render/render-job.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';

const NO_MESHES = new Map();
const scene = defaultScene();

describe('a render worker started ahead of its pool', () => {
  it('is taken by the next pool, which renders the same image as a tile rendered here', async () => {
    prestartRenderWorker();
    const pool = createNodeRenderPool(1);
    try {
      // The pool took the waiting thread: none is left for another.
      expect(takePrestartedRenderWorker()).toBeNull();
      const result = (await pool.render(scene, NO_MESHES, { width: 24, height: 16, preview: false }).done) as FinishedRender;
      expect(result.cancelled).toBe(false);
      const expected = renderTile(
        buildTracerScene(scene, NO_MESHES),
        { x: 0, y: 0, width: 24, height: 16 },
        { imageWidth: 24, imageHeight: 16, seed: 0 },
        emptyRayStats(),
      );
      expect(new Uint8Array(result.rgb.buffer)).toEqual(new Uint8Array(expected.buffer));
    } finally {
      pool.dispose();
    }
  });

  it('is started once however often it is asked for, and a death while it waited reaches the pool that takes it', async () => {
    const entry = pathToFileURL(fileURLToPath(new URL('../support/failing-to-start-worker.ts', import.meta.url))).href;
    const prestarted = prestartRenderWorker(entry);
    expect(prestartRenderWorker(entry)).toBe(prestarted);
    // Only a pool of the same entry takes it.
    expect(takePrestartedRenderWorker()).toBeNull();
    await vi.waitFor(() => expect(prestarted.failure).toMatch(/the test worker failed to start on purpose/), { timeout: 20_000 });
    const failures: string[] = [];
    const port = createNodeWorkerPort({ onResponse: () => {}, onFailure: (message) => failures.push(message) }, entry);
    await vi.waitFor(() => expect(failures).toEqual([prestarted.failure]));
    port.terminate();
    expect(takePrestartedRenderWorker(entry)).toBeNull();
  });

  it('is one thread at a time: asking for one of another entry replaces the one waiting', async () => {
    const entry = pathToFileURL(fileURLToPath(new URL('../support/failing-to-start-worker.ts', import.meta.url))).href;
    const first = prestartRenderWorker();
    const second = prestartRenderWorker(entry);
    expect(second).not.toBe(first);
    // The replaced thread is stopped (a thread no longer running has the id -1).
    await vi.waitFor(() => expect(first.worker.threadId).toBe(-1));
    expect(takePrestartedRenderWorker()).toBeNull();
    expect(takePrestartedRenderWorker(entry)).toBe(second);
    await second.worker.terminate();
  });
});
