import { describe, expect, it } from 'vitest';
import { pathToFileURL } from 'node:url';
import { RenderPool, RenderWorkersUnavailable, type RenderPoolOptions } from '../../src/render/render-pool.ts';
import type { FinishedRender, RenderResult } from '../../src/render/render-job.ts';
import { createNodeWorkerPort } from '../../src/cli/node-worker-port.ts';
import type { CreateRenderWorker } from '../../src/render/render-worker-port.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import { renderTile } from '../../src/tracer/render-tile.ts';
import { tracePixel } from '../../src/tracer/trace-pixel.ts';
import { buildTracerScene } from '../../src/tracer/tracer-scene.ts';
import { createRenderHandler } from '../../workers/render-core.ts';
import type { RenderResponse } from '../../workers/protocol.ts';

const NO_MESHES = new Map();
const scene = defaultScene();
const [WIDTH, HEIGHT] = [80, 60];
const fixture = (name: string) => pathToFileURL(new URL(`../support/${name}`, import.meta.url).pathname).href;

/** The image one renderTile over the whole image gives: what any pool must produce. */
function expectedImage(): Float32Array {
  return renderTile(
    buildTracerScene(scene, NO_MESHES),
    { x: 0, y: 0, width: WIDTH, height: HEIGHT },
    { imageWidth: WIDTH, imageHeight: HEIGHT, seed: 0 },
    emptyRayStats(),
  );
}

function finished(result: RenderResult): FinishedRender {
  if (result.cancelled) throw new Error('the render was cancelled');
  return result;
}

/**
 * A pool whose log is kept, with a silence allowance short enough for a test. Starting a
 * worker thread (and TypeScript in it) takes seconds on a busy machine: that counts as
 * building the scene.
 */
function poolWith(createWorker: CreateRenderWorker, options: Partial<RenderPoolOptions> = {}) {
  const log: string[] = [];
  const pool = new RenderPool({
    size: 2,
    createWorker,
    log: (message) => log.push(message),
    watchdog: { floorMs: 400, sceneBuildMs: 30_000, checkEveryMs: 50 },
    ...options,
  });
  return { pool, log };
}

/** An in-process worker (the real handler, no thread) whose responses `tamper` may replace or add to. */
function inProcessWorker(tamper: (response: RenderResponse, send: (data: unknown) => void) => void): CreateRenderWorker {
  return ({ onResponse }) => {
    const handle = createRenderHandler((response) => tamper(response, onResponse));
    return { post: (request) => handle(request), terminate: () => {} };
  };
}

describe('render workers whose code cannot be loaded', () => {
  /** A browser worker whose script is gone (a newer build) or out of reach: it fails at once, before it has started. */
  function unloadable(starts: { count: number }): CreateRenderWorker {
    return ({ onFailure }) => {
      starts.count++;
      queueMicrotask(() => onFailure('404', 'not-started'));
      return { post: () => {}, terminate: () => {} };
    };
  }

  it('are tried a bounded number of times, then every render and trace fails at once, with no more workers started', async () => {
    const starts = { count: 0 };
    const { pool, log } = poolWith(unloadable(starts), { size: 4 });
    try {
      const failed = pool.render(scene, NO_MESHES, { width: 20, height: 20 }).done;
      await expect(failed).rejects.toBeInstanceOf(RenderWorkersUnavailable);
      await expect(failed).rejects.toThrow("the render workers' code could not be loaded (404)");
      // The four first workers and the replacements of the first two failures.
      expect(starts.count).toBe(6);
      expect(log.at(-1)).toBe("the render workers' code could not be loaded (404)");
      // A pixel trace asked while they are tried waits for the last try, and fails with the same reason.
      for (let edit = 0; edit < 20; edit++) {
        await expect(pool.render(scene, NO_MESHES, { width: 20, height: 20 }).done).rejects.toBeInstanceOf(RenderWorkersUnavailable);
        await expect(pool.tracePixels(0, 4)).rejects.toBeInstanceOf(RenderWorkersUnavailable);
        await expect(pool.ready()).rejects.toBeInstanceOf(RenderWorkersUnavailable);
      }
      expect(starts.count).toBe(6);
    } finally {
      pool.dispose();
    }
  });

  it('a pixel trace asked of workers that cannot be loaded fails with RenderWorkersUnavailable after the tries', async () => {
    const starts = { count: 0 };
    const { pool } = poolWith(unloadable(starts), { size: 1 });
    try {
      pool.setScene(scene, NO_MESHES);
      await expect(pool.tracePixels(0, 4)).rejects.toBeInstanceOf(RenderWorkersUnavailable);
      expect(starts.count).toBe(3);
    } finally {
      pool.dispose();
    }
  });

  it('one that could not start while others work is replaced, and the render completes', async () => {
    let started = 0;
    const working = inProcessWorker((response, send) => send(response));
    const { pool, log } = poolWith((handlers) => {
      if (started++ !== 0) return working(handlers);
      queueMicrotask(() => handlers.onFailure('a dropped connection', 'not-started'));
      return { post: () => {}, terminate: () => {} };
    });
    try {
      const result = finished(await pool.render(scene, NO_MESHES, { width: WIDTH, height: HEIGHT }).done);
      expect(new Uint8Array(result.rgb.buffer)).toEqual(new Uint8Array(expectedImage().buffer));
      expect(log).toEqual(['a render worker could not start: a dropped connection']);
    } finally {
      pool.dispose();
    }
  });
});

describe('render workers that fail', () => {
  it('a worker that crashes: its tiles go to a replacement and the image is complete and right', async () => {
    let started = 0;
    const { pool, log } = poolWith((handlers) =>
      started++ === 0 ? createNodeWorkerPort(handlers, fixture('crashing-worker.ts')) : createNodeWorkerPort(handlers),
    );
    try {
      const result = finished(await pool.render(scene, NO_MESHES, { width: WIDTH, height: HEIGHT }).done);
      expect(new Uint8Array(result.rgb.buffer)).toEqual(new Uint8Array(expectedImage().buffer));
      expect(started).toBe(3);
      expect(log).toEqual([expect.stringMatching(/^a render worker stopped: the test worker crashed on purpose$/)]);
    } finally {
      pool.dispose();
    }
  });

  it('a worker that falls silent mid-render (no error, no exit): replaced after its deadline, the render completes', async () => {
    let started = 0;
    const { pool, log } = poolWith((handlers) =>
      started++ === 0 ? createNodeWorkerPort(handlers, fixture('silent-worker.ts')) : createNodeWorkerPort(handlers),
    );
    try {
      const result = finished(await pool.render(scene, NO_MESHES, { width: WIDTH, height: HEIGHT }).done);
      expect(new Uint8Array(result.rgb.buffer)).toEqual(new Uint8Array(expectedImage().buffer));
      expect(log).toEqual([expect.stringMatching(/^a render worker stopped answering \(silent for \d+ s\)$/)]);
    } finally {
      pool.dispose();
    }
  });

  it('a slow worker that still answers is left alone', async () => {
    const { pool, log } = poolWith(
      inProcessWorker((response, send) => setTimeout(() => send(response), response.type === 'tile-done' ? 150 : 0)),
      { size: 1 },
    );
    try {
      finished(await pool.render(scene, NO_MESHES, { width: 40, height: 30, preview: false }).done);
      expect(log).toEqual([]);
    } finally {
      pool.dispose();
    }
  });

  it('workers that crash again and again fail the job with the reason, and the pool renders once they work', async () => {
    let crashing = true;
    const { pool } = poolWith((handlers) => (crashing ? createNodeWorkerPort(handlers, fixture('crashing-worker.ts')) : createNodeWorkerPort(handlers)));
    try {
      await expect(pool.render(scene, NO_MESHES, { width: 20, height: 20 }).done).rejects.toThrow(/crashed on purpose/);
      crashing = false;
      expect(finished(await pool.render(scene, NO_MESHES, { width: 20, height: 20 }).done).width).toBe(20);
    } finally {
      pool.dispose();
    }
  });

  it('drops malformed messages with a logged reason and renders the right image from the good ones', async () => {
    const { pool, log } = poolWith(
      inProcessWorker((response, send) => {
        if (response.type === 'tile-done') {
          send(null);
          send({ type: 'tile-done', jobId: response.jobId });
          send({ ...response, rgb: new Float32Array(2) });
          send({ ...response, tileId: 99_999 });
          send({ type: 'gossip' });
        }
        send(response);
      }),
      { size: 1 },
    );
    try {
      const result = finished(await pool.render(scene, NO_MESHES, { width: WIDTH, height: HEIGHT }).done);
      expect(new Uint8Array(result.rgb.buffer)).toEqual(new Uint8Array(expectedImage().buffer));
      // Every tile brought each bad message once; the numbers differ from tile to tile.
      expect(new Set(log.map((line) => line.replace(/\d+/g, 'N')))).toEqual(
        new Set([
          'dropped a message from a render worker: not an object but null',
          'dropped a message from a render worker: a tile-done without job and tile ids and a time',
          'dropped a message from a render worker: tile N came back with N values instead of N',
          'dropped a message from a render worker: tile N was not given to this worker',
          'dropped a message from a render worker: an unknown type "gossip"',
        ]),
      );
    } finally {
      pool.dispose();
    }
  });

  it('a pixel trace on a worker that falls silent fails with the reason instead of waiting for ever', async () => {
    const { pool } = poolWith(
      inProcessWorker((response, send) => response.type !== 'pixel-traced' && send(response)),
      { size: 1 },
    );
    try {
      pool.setScene(scene, NO_MESHES);
      await pool.ready();
      await expect(pool.tracePixel(1, 1)).rejects.toThrow(/stopped answering/);
    } finally {
      pool.dispose();
    }
  });

  it('a block of pixel traces that comes back malformed is dropped, one of the wrong size fails its request', async () => {
    let tampered = 0;
    const { pool, log } = poolWith(
      inProcessWorker((response, send) => {
        if (response.type !== 'pixels-traced') return send(response);
        if (tampered++ === 0) send({ ...response, traces: 'no trees' });
        send(tampered === 1 ? response : { ...response, traces: response.traces.slice(1) });
      }),
      { size: 1 },
    );
    try {
      pool.setScene(scene, NO_MESHES);
      const core = buildTracerScene(scene, NO_MESHES);
      const columns = scene.camera.pixels[0];
      expect(await pool.tracePixels(1, 3, 5)).toEqual([1, 2, 3].map((i) => tracePixel(core, i % columns, Math.floor(i / columns), 5)));
      expect(log).toEqual(['dropped a message from a render worker: a pixels-traced without a request id and ray trees']);
      await expect(pool.tracePixels(0, 2)).rejects.toThrow('a render worker answered a trace-pixels request with a pixels-traced of the wrong size');
    } finally {
      pool.dispose();
    }
  });
});
