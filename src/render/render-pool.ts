/**
 * A pool of render workers that turns one render into tiles, hands them to idle workers,
 * assembles the image and reports progress; it also answers the lab's ray-tree queries.
 * Platform-free: the browser (web-worker-port.ts) and Node (src/cli/node-worker-port.ts)
 * pass in how to start a worker and how many.
 *
 * One job runs at a time: a new `render()` cancels the one before. The workers keep the last
 * scene they were sent and get a new `load-scene` only when `scene` or `meshes` is a
 * different object than last time, so pass a new object after every change (never mutate).
 */
import type { FailedRequest, RenderResponse } from '../../workers/protocol.ts';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import type { Scene } from '../scene/scene.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import { DEFAULT_SEED, type RenderJob, type RenderOptions, type RenderResult } from './render-job.ts';
import type { CreateRenderWorker, RenderWorkerPort } from './render-worker-port.ts';
import { planPasses } from './render-passes.ts';
import { TiledRender } from './tiled-render.ts';

/**
 * Tiles posted to a worker ahead of their turn: while one renders, the next is already
 * queued, which hides the message round trip. More would not speed anything up and would
 * leave workers idle at the end of an image while others still hold queued tiles.
 */
const TILES_IN_FLIGHT = 2;

interface PoolWorker {
  port: RenderWorkerPort;
  /** The scene version last sent to this worker. */
  sceneId: number | null;
  /** The scene version this worker has finished building. */
  builtSceneId: number | null;
  /** Tiles of the current job posted to it and not back yet. */
  inFlight: number;
  /** Names of the models already sent to it (it keeps them; see LoadSceneRequest). */
  models: Set<string>;
}

interface ActiveJob {
  id: number;
  sceneId: number;
  seed: number;
  tiles: TiledRender;
  startedAt: number;
  sceneMs: number;
  resolve(result: RenderResult): void;
  reject(error: Error): void;
}

interface Waiter {
  resolve(): void;
  reject(error: Error): void;
}

interface PendingTrace {
  worker: PoolWorker;
  resolve(trace: PixelTrace): void;
  reject(error: Error): void;
}

export interface RenderPoolOptions {
  createWorker: CreateRenderWorker;
  /** Number of workers, at least 1; the adapters default it to the machine's cores. */
  size: number;
}

export class RenderPool {
  readonly size: number;
  private readonly createWorker: CreateRenderWorker;
  /** null: the worker died; a new one starts when the pool next needs it. */
  private readonly workers: (PoolWorker | null)[];
  private scene: { id: number; scene: Scene; meshes: MeshLibrary } | null = null;
  private job: ActiveJob | null = null;
  private readonly traces = new Map<number, PendingTrace>();
  private readonly readyWaiters: Waiter[] = [];
  /** Source of scene, job and request ids. */
  private lastId = 0;
  private disposed = false;

  constructor({ createWorker, size }: RenderPoolOptions) {
    if (!Number.isInteger(size) || size < 1) {
      throw new RangeError(`a render pool needs a whole number of workers, at least 1, got ${size}`);
    }
    this.size = size;
    this.createWorker = createWorker;
    this.workers = Array.from({ length: size }, () => this.spawn());
  }

  /**
   * Sends the scene to the workers (they build it once for all later tiles and traces).
   * `render` does this itself; call it to trace pixels without rendering. A different scene
   * cancels the running job.
   */
  setScene(scene: Scene, meshes: MeshLibrary): void {
    this.assertOpen();
    this.useScene(scene, meshes);
  }

  /**
   * Renders the scene at `options.width × options.height` (default: settings.imageSize),
   * cancelling the job before. See RenderJob for how it ends.
   */
  render(scene: Scene, meshes: MeshLibrary, options: RenderOptions = {}): RenderJob {
    this.assertOpen();
    const width = options.width ?? scene.settings.imageSize[0];
    const height = options.height ?? scene.settings.imageSize[1];
    if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1) {
      throw new RangeError(`the image size must be whole numbers of at least 1 pixel, got ${width}×${height}`);
    }
    this.cancelJob();
    const sceneId = this.useScene(scene, meshes);
    const tiles = new TiledRender(width, height, planPasses(scene, options.preview ?? true), options);
    const id = ++this.lastId;
    const done = new Promise<RenderResult>((resolve, reject) => {
      this.job = {
        id,
        sceneId,
        seed: options.seed ?? DEFAULT_SEED,
        tiles,
        startedAt: performance.now(),
        sceneMs: 0,
        resolve,
        reject,
      };
    });
    this.pump();
    return {
      image: tiles.image,
      done,
      cancel: () => {
        if (this.job?.id === id) this.cancelJob();
      },
    };
  }

  /**
   * Resolves once every worker has built the current scene, i.e. after the threads have
   * started and the BVHs are built; rejects with the reason when one cannot. `rt render`
   * waits for it so that its timing measures the render alone.
   */
  ready(): Promise<void> {
    this.assertOpen();
    if (!this.scene) return Promise.reject(new Error('there is no scene: render or set one first'));
    for (const worker of this.liveWorkers()) this.sendScene(worker);
    return new Promise((resolve, reject) => {
      this.readyWaiters.push({ resolve, reject });
      this.settleReady();
    });
  }

  /** The ray tree of pixel (x, y) of the camera's small screen, in the scene last rendered or set. */
  tracePixel(x: number, y: number, seed = DEFAULT_SEED): Promise<PixelTrace> {
    this.assertOpen();
    if (!this.scene) return Promise.reject(new Error('there is no scene to trace: render or set one first'));
    // The least busy worker answers soonest: traces skip the tiles queued before them.
    const worker = this.liveWorkers().reduce((best, w) => (w.inFlight < best.inFlight ? w : best));
    this.sendScene(worker);
    const requestId = ++this.lastId;
    return new Promise((resolve, reject) => {
      this.traces.set(requestId, { worker, resolve, reject });
      worker.port.post({ type: 'trace-pixel', requestId, x, y, seed });
    });
  }

  /** Cancels the job, fails pending traces and stops every worker; the pool is unusable after. */
  dispose(): void {
    if (this.disposed) return;
    this.cancelJob();
    for (const [requestId, trace] of this.traces) {
      this.traces.delete(requestId);
      trace.reject(new Error('the render pool was closed'));
    }
    this.settleReady(new Error('the render pool was closed'));
    for (const worker of this.workers) worker?.port.terminate();
    this.workers.fill(null);
    this.disposed = true;
  }

  private spawn(): PoolWorker {
    const worker: PoolWorker = {
      sceneId: null,
      builtSceneId: null,
      inFlight: 0,
      models: new Set(),
      port: this.createWorker({
        onResponse: (response) => this.onResponse(worker, response),
        onFailure: (message) => this.onWorkerFailed(worker, message),
      }),
    };
    return worker;
  }

  private liveWorkers(): PoolWorker[] {
    for (let slot = 0; slot < this.workers.length; slot++) this.workers[slot] ??= this.spawn();
    return this.workers.filter((worker) => worker !== null);
  }

  /** Makes `scene` the workers' scene (a different one cancels the job) and returns its id. */
  private useScene(scene: Scene, meshes: MeshLibrary): number {
    if (this.scene?.scene === scene && this.scene.meshes === meshes) return this.scene.id;
    this.cancelJob();
    this.scene = { id: ++this.lastId, scene, meshes };
    for (const worker of this.liveWorkers()) this.sendScene(worker);
    return this.scene.id;
  }

  private sendScene(worker: PoolWorker): void {
    if (!this.scene || worker.sceneId === this.scene.id) return;
    const { id, scene, meshes } = this.scene;
    const unsent = new Map([...meshes].filter(([name]) => !worker.models.has(name)));
    worker.port.post({ type: 'load-scene', sceneId: id, scene, meshes: unsent });
    for (const name of unsent.keys()) worker.models.add(name);
    worker.sceneId = id;
  }

  /** Keeps every worker TILES_IN_FLIGHT tiles busy while the current pass has tiles left. */
  private pump(): void {
    const job = this.job;
    if (!job) return;
    const { width, height } = job.tiles.image;
    for (const worker of this.liveWorkers()) {
      while (worker.inFlight < TILES_IN_FLIGHT) {
        const next = job.tiles.takeTile();
        if (!next) return;
        this.sendScene(worker);
        worker.port.post({
          type: 'render-tile',
          jobId: job.id,
          tileId: next.tileId,
          tile: next.tile,
          options: { imageWidth: width, imageHeight: height, seed: job.seed, block: next.block },
        });
        worker.inFlight++;
      }
    }
  }

  private onResponse(worker: PoolWorker, response: RenderResponse): void {
    switch (response.type) {
      case 'scene-ready':
        worker.builtSceneId = response.sceneId;
        if (this.job?.sceneId === response.sceneId) this.job.sceneMs = Math.max(this.job.sceneMs, response.ms);
        this.settleReady();
        break;
      case 'tile-done': {
        const job = this.job;
        if (job?.id !== response.jobId) return; // a late tile of a cancelled job
        worker.inFlight--;
        try {
          job.tiles.accept(response.tileId, response.rgb, response.stats, response.ms);
        } finally {
          this.continueJob(job); // even when a progress or preview callback threw
        }
        break;
      }
      case 'pixel-traced':
        this.takeTrace(response.requestId)?.resolve(response.trace);
        break;
      case 'error':
        this.onRequestFailed(response.failed, response.message);
        break;
    }
  }

  private onRequestFailed(failed: FailedRequest, message: string): void {
    switch (failed.type) {
      case 'load-scene':
        if (this.job?.sceneId === failed.sceneId) this.failJob(message);
        if (this.scene?.id === failed.sceneId) this.settleReady(new Error(message));
        break;
      case 'render-tile':
        if (this.job?.id === failed.jobId) this.failJob(message);
        break;
      case 'trace-pixel':
        this.takeTrace(failed.requestId)?.reject(new Error(message));
        break;
    }
  }

  /** A dead worker fails the job and its traces; its slot gets a new worker on next use. */
  private onWorkerFailed(worker: PoolWorker, message: string): void {
    const slot = this.workers.indexOf(worker);
    if (slot < 0) return;
    this.workers[slot] = null;
    worker.port.terminate();
    const reason = `a render worker stopped: ${message}`;
    if (this.job) this.failJob(reason);
    this.settleReady(new Error(reason));
    for (const [requestId, trace] of this.traces) {
      if (trace.worker === worker) this.takeTrace(requestId)?.reject(new Error(reason));
    }
  }

  /** Answers `ready()` callers: with `error`, or when every worker has built the current scene. */
  private settleReady(error?: Error): void {
    const sceneId = this.scene?.id;
    if (!error && !this.workers.every((worker) => worker?.builtSceneId === sceneId)) return;
    for (const waiter of this.readyWaiters.splice(0)) {
      if (error) waiter.reject(error);
      else waiter.resolve();
    }
  }

  private takeTrace(requestId: number): PendingTrace | undefined {
    const trace = this.traces.get(requestId);
    this.traces.delete(requestId);
    return trace;
  }

  private continueJob(job: ActiveJob): void {
    if (this.job !== job) return; // a progress or preview callback started another render
    if (job.tiles.finished) this.finishJob(job);
    else this.pump();
  }

  private finishJob(job: ActiveJob): void {
    this.endJob();
    job.resolve({
      cancelled: false,
      ...job.tiles.image,
      stats: job.tiles.stats,
      ms: performance.now() - job.startedAt,
      workers: this.size,
      slowestTileMs: job.tiles.slowestTileMs,
      sceneMs: job.sceneMs,
    });
  }

  private cancelJob(): void {
    this.endJob()?.resolve({ cancelled: true });
  }

  private failJob(message: string): void {
    this.endJob()?.reject(new Error(message));
  }

  /** Detaches the current job: workers drop its queued tiles and late ones are ignored. */
  private endJob(): ActiveJob | null {
    const job = this.job;
    if (!job) return null;
    this.job = null;
    for (const worker of this.workers) {
      if (worker && worker.inFlight > 0) worker.port.post({ type: 'cancel', jobId: job.id });
      if (worker) worker.inFlight = 0;
    }
    return job;
  }

  private assertOpen(): void {
    if (this.disposed) throw new Error('this render pool has been closed');
  }
}
