/**
 * The contracts of RenderJob.cancel and of RenderPool's one-job-at-a-time rule, in the words
 * of their doc comments, checked against scripted workers: each records what the pool posts
 * to it and answers only when the test says so. No clock is read: what is checked is what
 * the pool tells its workers and in which order, not how fast a machine does it.
 */
import { describe, expect, it } from 'vitest';
import { RenderPool } from '../../src/render/render-pool.ts';
import type { RenderResult } from '../../src/render/render-job.ts';
import type { RenderWorkerHandlers } from '../../src/render/render-worker-port.ts';
import { defaultScene } from '../../src/scene/scene-defaults.ts';
import { emptyRayStats } from '../../src/tracer/ray-tree.ts';
import type { RenderRequest, RenderTileRequest } from '../../workers/protocol.ts';

const NO_MESHES = new Map();
const scene = defaultScene();
/** Several tiles per worker, so that each holds queued tiles when a job ends. */
const SIZE = { width: 120, height: 90, preview: false };

/** A worker that builds every scene at once and renders a tile only when `finish` is called. */
class ScriptedWorker {
  readonly posts: RenderRequest[] = [];
  constructor(private readonly handlers: RenderWorkerHandlers) {}

  post(request: RenderRequest): void {
    this.posts.push(request);
    if (request.type === 'load-scene') this.handlers.onResponse({ type: 'scene-ready', sceneId: request.sceneId, ms: 0 });
  }

  terminate(): void {}

  /** Tiles posted and not yet answered or cancelled, in the order they were posted. */
  queued(): RenderTileRequest[] {
    const cancelled = new Set(this.posts.flatMap((p) => (p.type === 'cancel' ? [p.jobId] : [])));
    return this.posts.filter((p): p is RenderTileRequest => p.type === 'render-tile' && !cancelled.has(p.jobId) && !this.answered.has(p));
  }

  /** Answers a tile with a flat grey, as a worker would that rendered it. */
  finish(tile: RenderTileRequest): void {
    this.answered.add(tile);
    const rgb = new Float32Array(tile.tile.width * tile.tile.height * 3).fill(0.5);
    this.handlers.onResponse({ type: 'tile-done', jobId: tile.jobId, tileId: tile.tileId, rgb, stats: emptyRayStats(), ms: 1 });
  }

  private readonly answered = new Set<RenderTileRequest>();
}

function scriptedPool(size = 2): { pool: RenderPool; workers: ScriptedWorker[] } {
  const workers: ScriptedWorker[] = [];
  const pool = new RenderPool({
    size,
    log: (message) => {
      throw new Error(`unexpected pool log: ${message}`);
    },
    createWorker: (handlers) => {
      const worker = new ScriptedWorker(handlers);
      workers.push(worker);
      return worker;
    },
  });
  return { pool, workers };
}

/** Answers every queued tile of job `jobId`, round after round, until the job has none left. */
function finishJob(workers: ScriptedWorker[], jobId: number): void {
  for (let round = 0; round < 10_000; round++) {
    const next = workers.flatMap((w) =>
      w
        .queued()
        .filter((t) => t.jobId === jobId)
        .slice(0, 1)
        .map((t) => [w, t] as const),
    );
    if (next.length === 0) return;
    for (const [worker, tile] of next) worker.finish(tile);
  }
  throw new Error(`job ${jobId} never ran out of tiles`);
}

const jobIdOf = (worker: ScriptedWorker) => (worker.posts.findLast((p) => p.type === 'render-tile') as RenderTileRequest).jobId;
const settled = (done: Promise<RenderResult>) => Promise.race([done, Promise.resolve('still running' as const)]);

describe('RenderJob.cancel: "Stops the job … Safe to call twice."', () => {
  it('a stale handle cannot cancel the job that replaced it', async () => {
    const { pool, workers } = scriptedPool();
    try {
      const old = pool.render(scene, NO_MESHES, SIZE);
      const current = pool.render(scene, NO_MESHES, SIZE);
      const currentId = jobIdOf(workers[0]);
      const postsBefore = workers.map((w) => w.posts.length);

      old.cancel();
      old.cancel();

      expect(await old.done).toEqual({ cancelled: true });
      // Nothing was posted for the current job: its workers were not told to drop it.
      expect(workers.map((w) => w.posts.length)).toEqual(postsBefore);
      expect(await settled(current.done)).toBe('still running');
      finishJob(workers, currentId);
      expect(await current.done).toMatchObject({ cancelled: false, width: SIZE.width, height: SIZE.height });
    } finally {
      pool.dispose();
    }
  });

  it('the handle of a finished job cannot cancel the next one either', async () => {
    const { pool, workers } = scriptedPool();
    try {
      const first = pool.render(scene, NO_MESHES, SIZE);
      finishJob(workers, jobIdOf(workers[0]));
      expect((await first.done).cancelled).toBe(false);

      const next = pool.render(scene, NO_MESHES, SIZE);
      first.cancel();
      finishJob(workers, jobIdOf(workers[0]));
      expect((await next.done).cancelled).toBe(false);
    } finally {
      pool.dispose();
    }
  });
});

describe('RenderPool.endJob: "workers drop its queued tiles and late ones are ignored"', () => {
  it('cancel() tells every worker that holds tiles of the job to drop them', async () => {
    const { pool, workers } = scriptedPool();
    try {
      const job = pool.render(scene, NO_MESHES, SIZE);
      const jobId = jobIdOf(workers[0]);
      expect(workers.every((w) => w.queued().length > 0)).toBe(true);

      job.cancel();

      for (const worker of workers) expect(worker.posts.at(-1)).toEqual({ type: 'cancel', jobId });
      expect(await job.done).toEqual({ cancelled: true });
    } finally {
      pool.dispose();
    }
  });

  it('a new render takes over at once: each worker is told to drop the old tiles before it gets the new ones', () => {
    const { pool, workers } = scriptedPool();
    try {
      pool.render(scene, NO_MESHES, SIZE);
      const oldId = jobIdOf(workers[0]);
      pool.render(scene, NO_MESHES, SIZE);
      const newId = jobIdOf(workers[0]);

      expect(newId).not.toBe(oldId);
      for (const worker of workers) {
        const kinds = worker.posts.map((p) => (p.type === 'render-tile' ? `tile of ${p.jobId === oldId ? 'old' : 'new'}` : p.type));
        const cancel = kinds.indexOf('cancel');
        // Within render() itself, without waiting for any tile: the worker's queue holds
        // the new job's tiles behind at most the old tile it is rendering.
        expect(cancel).toBeGreaterThan(kinds.lastIndexOf('tile of old'));
        expect(kinds.indexOf('tile of new')).toBeGreaterThan(cancel);
        expect(worker.posts[cancel]).toEqual({ type: 'cancel', jobId: oldId });
      }
    } finally {
      pool.dispose();
    }
  });

  it('a late tile of the replaced job changes neither the new image nor its progress', async () => {
    const { pool, workers } = scriptedPool(1);
    try {
      pool.render(scene, NO_MESHES, SIZE);
      const lateTile = workers[0].queued()[0];
      const reports: number[] = [];
      const current = pool.render(scene, NO_MESHES, { ...SIZE, onProgress: (p) => reports.push(p.done) });

      workers[0].finish(lateTile);

      expect(reports).toEqual([]);
      expect(current.image.rgb.every((c) => c === 0)).toBe(true);
      finishJob(workers, jobIdOf(workers[0]));
      expect((await current.done).cancelled).toBe(false);
    } finally {
      pool.dispose();
    }
  });
});
