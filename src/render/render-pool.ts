/**
 * A pool of render workers that turns one render into tiles, hands them to idle workers,
 * assembles the image and reports progress; it also answers the lab's ray-tree queries.
 * Platform-free: the browser (web-worker-port.ts) and Node (src/cli/node-worker-port.ts)
 * pass in how to start a worker and how many.
 *
 * One job runs at a time: a new `render()` cancels the one before. The workers keep the last
 * scene they were sent and get a new `load-scene` only when `scene` or `meshes` is a
 * different object than last time, so pass a new object after every change (never mutate).
 *
 * A worker cannot hang a render. One that dies (an error event) or goes silent (a browser
 * worker that closes itself raises no event at all) is replaced and its tiles go to the
 * next free worker. Silence is judged against a deadline scaled to the work it holds: the
 * render estimate's rays for its tiles (render-estimate.ts), at the slower of the assumed
 * and the measured speed, times a wide margin, plus time to build the scene. Only when
 * workers fail several times in a row, with no good answer in between, does the job fail.
 * Messages that are not well-formed responses are dropped and logged.
 *
 * A worker whose code cannot be loaded (a browser tab of a build that a newer one replaced
 * on the server, offline with no stored copy) is not a crash a new worker mends: after a
 * few in a row the pool gives up for good (until the page is reloaded) and fails every job
 * and trace with `RenderWorkersUnavailable`, starting no more workers, so that the page can
 * say so with a Reload button instead of asking the server again at every edit.
 */
import type {
  FailedRequest,
  PathsTracedResponse,
  PixelsTracedResponse,
  PixelTracedResponse,
  RayBudget,
  RenderRequest,
  RenderResponse,
} from '../../workers/protocol.ts';
import type { LabPaths } from '../tracer/lab-paths.ts';
import type { MeshLibrary } from '../scene/mesh-data.ts';
import type { Scene } from '../scene/scene.ts';
import type { PixelTrace } from '../tracer/ray-tree.ts';
import type { RenderTileOptions } from '../tracer/tile.ts';
import { DEFAULT_SEED, type RenderJob, type RenderOptions, type RenderResult } from './render-job.ts';
import type { CreateRenderWorker, RenderWorkerPort } from './render-worker-port.ts';
import { planPasses, tracedSamples } from './render-passes.ts';
import { primaryRaysPerSample, RAYS_PER_SECOND_PER_WORKER, raysPerSample } from './render-estimate.ts';
import { checkResponse } from './render-response-check.ts';
import { TiledRender, type TileAssignment } from './tiled-render.ts';

/**
 * Tiles posted to a worker ahead of their turn: while one renders, the next is already
 * queued, which hides the message round trip. More would not speed anything up and would
 * leave workers idle at the end of an image while others still hold queued tiles.
 */
const TILES_IN_FLIGHT = 2;

/** How patient the pool is with a silent worker (see the file comment). */
export interface WatchdogOptions {
  /** Silence allowed on top of the work's estimate: message delays, a busy machine. */
  floorMs: number;
  /** The margin on a tile's estimated time. */
  slack: number;
  /** Silence allowed while a worker builds a new scene (BVHs of large models). */
  sceneBuildMs: number;
  /** How often the deadlines are checked. */
  checkEveryMs: number;
}

export const DEFAULT_WATCHDOG: WatchdogOptions = { floorMs: 5000, slack: 10, sceneBuildMs: 60_000, checkEveryMs: 1000 };

/** Workers failing this many times in a row, with no good answer in between, fail the job (a scene that crashes every worker). */
const FAILURES_IN_A_ROW = 3;

/** Workers whose code could not be loaded, in a row with no good answer between: then the pool gives up (one load and two more tries, as lazy-module.ts). */
const START_TRIES = 3;

/** The render workers' code cannot be loaded: only a reload of the page helps (see the file comment). */
export class RenderWorkersUnavailable extends Error {
  override readonly name = 'RenderWorkersUnavailable';
}

/** The assumed cost of one ray, before a tile has measured it. */
const ASSUMED_MS_PER_RAY = 1000 / RAYS_PER_SECOND_PER_WORKER;

interface PoolWorker {
  port: RenderWorkerPort;
  /** The scene version last sent to this worker. */
  sceneId: number | null;
  /** The scene version this worker has finished building. */
  builtSceneId: number | null;
  /** The scene version it last answered for, built or failed. */
  answeredSceneId: number | null;
  /** Tiles of the current job posted to it and not back yet, with their estimated rays. */
  tiles: Map<number, { assignment: TileAssignment; rays: number }>;
  /** Names of the models already sent to it (it keeps them; see LoadSceneRequest). */
  models: Set<string>;
  /** When it last answered, or was given work while idle: its silence counts from here. */
  heardAt: number;
}

interface ActiveJob {
  id: number;
  sceneId: number;
  seed: number;
  tiles: TiledRender;
  startedAt: number;
  sceneMs: number;
  /** Rays of one sample of the scene, its lens and time rays included (render-estimate.ts), for the tiles' deadlines. */
  raysPerSample: number;
  /** The slowest cost per estimated ray a tile has shown, never below the assumed one. */
  msPerRay: number;
  resolve(result: RenderResult): void;
  reject(error: Error): void;
}

interface Waiter {
  resolve(): void;
  reject(error: Error): void;
}

/** The requests that ask for a pixel's rays or paths, and their answers. */
type TraceRequestType = 'trace-pixel' | 'trace-pixels' | 'trace-paths';
type TraceAnswer = PixelTracedResponse | PixelsTracedResponse | PathsTracedResponse;

interface PendingTrace {
  worker: PoolWorker;
  /** As posted: asked again of another worker when this one could not start. */
  request: Extract<RenderRequest, { type: TraceRequestType }>;
  /** The worker's answer: `pixel-traced` for tracePixel, `pixels-traced` for tracePixels, `paths-traced` for tracePaths. */
  resolve(answer: TraceAnswer): void;
  reject(error: Error): void;
}

export interface RenderPoolOptions {
  createWorker: CreateRenderWorker;
  /** Number of workers, at least 1; the adapters default it to the machine's cores. */
  size: number;
  /** Where dropped messages and replaced workers are reported; console.warn by default. */
  log?: (message: string) => void;
  watchdog?: Partial<WatchdogOptions>;
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
  private readonly log: (message: string) => void;
  private readonly watchdog: WatchdogOptions;
  private watchTimer: ReturnType<typeof setInterval> | undefined;
  private failuresInARow = 0;
  private startFailuresInARow = 0;
  /** Set once workers' code could not be loaded START_TRIES times: no worker is started again. */
  private unavailable: RenderWorkersUnavailable | null = null;

  constructor({ createWorker, size, log, watchdog }: RenderPoolOptions) {
    if (!Number.isInteger(size) || size < 1) {
      throw new RangeError(`a render pool needs a whole number of workers, at least 1, got ${size}`);
    }
    this.size = size;
    this.createWorker = createWorker;
    this.log = log ?? ((message) => console.warn(`render pool: ${message}`));
    this.watchdog = { ...DEFAULT_WATCHDOG, ...watchdog };
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
    this.failuresInARow = 0; // each render gets its own tries
    const sceneId = this.useScene(scene, meshes);
    const passes = planPasses(scene, { width, height, workers: this.size, preview: options.preview ?? true, oneSample: options.oneSample });
    const estimatedRaysPerSample = raysPerSample(scene) * primaryRaysPerSample(scene);
    const tiles = new TiledRender(width, height, passes, options, estimatedRaysPerSample);
    if (this.unavailable) return { image: tiles.image, done: Promise.reject(this.unavailable), cancel: () => {}, changes: () => tiles.takeChanges() };
    const id = ++this.lastId;
    const done = new Promise<RenderResult>((resolve, reject) => {
      this.job = {
        id,
        sceneId,
        seed: options.seed ?? DEFAULT_SEED,
        tiles,
        startedAt: performance.now(),
        sceneMs: 0,
        raysPerSample: estimatedRaysPerSample,
        msPerRay: ASSUMED_MS_PER_RAY,
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
      changes: () => tiles.takeChanges(),
    };
  }

  /**
   * Resolves once every worker has built the current scene, i.e. after the threads have
   * started and the BVHs are built; rejects with the reason when one cannot. `rt render`
   * waits for it so that its timing measures the render alone.
   */
  ready(): Promise<void> {
    this.assertOpen();
    if (this.unavailable) return Promise.reject(this.unavailable);
    if (!this.scene) return Promise.reject(new Error('there is no scene: render or set one first'));
    for (const worker of this.liveWorkers()) this.sendScene(worker);
    return new Promise((resolve, reject) => {
      this.readyWaiters.push({ resolve, reject });
      this.settleReady();
    });
  }

  /**
   * The ray tree of pixel (x, y) of the camera's small screen, in the scene last rendered or set;
   * with `terms`, every hit carries its shading terms (the ray debugger).
   */
  tracePixel(x: number, y: number, seed = DEFAULT_SEED, terms = false): Promise<PixelTrace> {
    return this.askForTraces({ type: 'trace-pixel', requestId: 0, x, y, seed, ...(terms ? { terms } : {}) }, (answer) =>
      answer.type === 'pixel-traced' ? answer.trace : null,
    );
  }

  /**
   * The ray trees of `count` pixels of the camera's small screen from pixel index `first`
   * (row-major over camera.pixels), in one message each way (the lab's screen); with a
   * `budget`, about that many of their rays (tree-budget.ts).
   */
  tracePixels(first: number, count: number, seed = DEFAULT_SEED, budget?: RayBudget): Promise<PixelTrace[]> {
    return this.askForTraces({ type: 'trace-pixels', requestId: 0, first, count, seed, ...(budget ? { budget } : {}) }, (answer) =>
      answer.type === 'pixels-traced' && answer.traces.length === count ? answer.traces : null,
    );
  }

  /**
   * The first `keep` sample paths of pixel (x, y) of the camera's screen in path mode, and
   * every path's contribution (lab-paths.ts), in the scene last rendered or set.
   */
  tracePaths(x: number, y: number, keep: number, seed = DEFAULT_SEED): Promise<LabPaths> {
    return this.askForTraces({ type: 'trace-paths', requestId: 0, x, y, seed, keep }, (answer) => (answer.type === 'paths-traced' ? answer.paths : null));
  }

  /** Posts a pixel-trace request (its requestId is assigned here); `read` takes the answer apart, null for a wrong one. */
  private askForTraces<T>(request: Extract<RenderRequest, { type: TraceRequestType }>, read: (answer: TraceAnswer) => T | null): Promise<T> {
    this.assertOpen();
    if (this.unavailable) return Promise.reject(this.unavailable);
    if (!this.scene) return Promise.reject(new Error('there is no scene to trace: render or set one first'));
    // The least busy worker answers soonest: traces skip the tiles queued before them.
    const worker = this.liveWorkers().reduce((best, w) => (w.tiles.size < best.tiles.size ? w : best));
    this.sendScene(worker);
    const requestId = ++this.lastId;
    return new Promise((resolve, reject) => {
      const resolveAnswer = (answer: TraceAnswer) => {
        const value = read(answer);
        if (value === null) reject(new Error(`a render worker answered a ${request.type} request with a ${answer.type} of the wrong size`));
        else resolve(value);
      };
      const posted = { ...request, requestId };
      this.post(worker, posted, () => this.traces.set(requestId, { worker, request: posted, resolve: resolveAnswer, reject }));
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
    this.stopWatching();
    this.disposed = true;
  }

  private spawn(): PoolWorker {
    const worker: PoolWorker = {
      sceneId: null,
      builtSceneId: null,
      answeredSceneId: null,
      tiles: new Map(),
      models: new Set(),
      heardAt: performance.now(),
      port: this.createWorker({
        onResponse: (data) => this.onMessage(worker, data),
        onFailure: (message, kind) =>
          kind === 'not-started' ? this.notStarted(worker, message) : this.replaceWorker(worker, `a render worker stopped: ${message}`),
      }),
    };
    return worker;
  }

  /**
   * Posts to a worker; a worker that was idle starts its deadline now. `register` records
   * the work first, as a worker in the same thread (tests) answers during the post.
   */
  private post(worker: PoolWorker, request: RenderRequest, register: () => void): void {
    if (!this.isBusy(worker)) worker.heardAt = performance.now();
    register();
    this.startWatching();
    worker.port.post(request);
  }

  /** Whether the worker owes an answer: a scene to build, tiles, or a pixel trace. */
  private isBusy(worker: PoolWorker): boolean {
    if (worker.sceneId !== worker.answeredSceneId || worker.tiles.size > 0) return true;
    for (const trace of this.traces.values()) if (trace.worker === worker) return true;
    return false;
  }

  /** How long the worker may stay silent with the work it holds (see the file comment). */
  private allowanceMs(worker: PoolWorker): number {
    const { floorMs, slack, sceneBuildMs } = this.watchdog;
    let rays = 0;
    for (const tile of worker.tiles.values()) rays += tile.rays;
    const building = worker.sceneId !== worker.builtSceneId ? sceneBuildMs : 0;
    return floorMs + building + slack * rays * (this.job?.msPerRay ?? ASSUMED_MS_PER_RAY);
  }

  private startWatching(): void {
    if (this.watchTimer !== undefined) return;
    this.watchTimer = setInterval(() => this.checkDeadlines(), this.watchdog.checkEveryMs);
    // In Node, a pool with nothing to do must not keep the process alive.
    (this.watchTimer as { unref?: () => void }).unref?.();
  }

  private stopWatching(): void {
    clearInterval(this.watchTimer);
    this.watchTimer = undefined;
  }

  /** Replaces every worker that has been silent past its allowance; stops when none is busy. */
  private checkDeadlines(): void {
    const now = performance.now();
    let busy = false;
    for (const worker of [...this.workers]) {
      if (!worker || !this.isBusy(worker)) continue;
      busy = true;
      const silentMs = now - worker.heardAt;
      if (silentMs > this.allowanceMs(worker)) this.replaceWorker(worker, `a render worker stopped answering (silent for ${Math.round(silentMs / 1000)} s)`);
    }
    if (!busy) this.stopWatching();
  }

  private liveWorkers(): PoolWorker[] {
    if (this.unavailable) return [];
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
    this.post(worker, { type: 'load-scene', sceneId: id, scene, meshes: unsent }, () => {
      for (const name of unsent.keys()) worker.models.add(name);
      worker.sceneId = id;
    });
  }

  /** Keeps every worker TILES_IN_FLIGHT tiles busy while the current pass has tiles left. */
  private pump(): void {
    const job = this.job;
    if (!job) return;
    const { width, height } = job.tiles.image;
    for (const worker of this.liveWorkers()) {
      while (worker.tiles.size < TILES_IN_FLIGHT) {
        const next = job.tiles.takeTile();
        if (!next) return;
        this.sendScene(worker);
        const options: RenderTileOptions = { imageWidth: width, imageHeight: height, seed: job.seed, block: next.block, samplesPerPixel: next.samplesPerPixel };
        // A progressive path pass: the worker carries the tile's sums of paths on (path-passes.ts).
        if (next.firstPath !== undefined) Object.assign(options, { firstPath: next.firstPath, pathSums: job.tiles.sumsOf(next.tile) });
        const request: RenderRequest = { type: 'render-tile', jobId: job.id, tileId: next.tileId, tile: next.tile, options };
        const rays = tracedSamples(next.tile, next) * job.raysPerSample;
        this.post(worker, request, () => worker.tiles.set(next.tileId, { assignment: next, rays }));
      }
    }
  }

  /** A message from a worker: checked, then handled; a malformed one is dropped and logged. */
  private onMessage(worker: PoolWorker, data: unknown): void {
    if (!this.workers.includes(worker)) return; // replaced: its late words do not count
    const checked = checkResponse(data);
    if (!checked.ok) {
      this.log(`dropped a message from a render worker: ${checked.reason}`);
      return;
    }
    worker.heardAt = performance.now();
    this.startFailuresInARow = 0;
    this.onResponse(worker, checked.response);
  }

  private onResponse(worker: PoolWorker, response: RenderResponse): void {
    switch (response.type) {
      case 'scene-ready':
        this.failuresInARow = 0;
        worker.builtSceneId = response.sceneId;
        worker.answeredSceneId = response.sceneId;
        if (this.job?.sceneId === response.sceneId) this.job.sceneMs = Math.max(this.job.sceneMs, response.ms);
        this.settleReady();
        break;
      case 'tile-done': {
        const job = this.job;
        if (job?.id !== response.jobId) return; // a late tile of a cancelled job
        const posted = worker.tiles.get(response.tileId);
        const problem = posted ? job.tiles.problemWith(response.tileId, response.rgb) : `tile ${response.tileId} was not given to this worker`;
        if (problem !== null) {
          this.log(`dropped a message from a render worker: ${problem}`);
          return;
        }
        this.failuresInARow = 0;
        worker.tiles.delete(response.tileId);
        if (posted && posted.rays > 0) job.msPerRay = Math.max(job.msPerRay, response.ms / posted.rays);
        try {
          job.tiles.accept(response.tileId, response.rgb, response.stats, response.ms);
        } finally {
          this.continueJob(job); // even when a progress or preview callback threw
        }
        break;
      }
      case 'pixel-traced':
      case 'pixels-traced':
      case 'paths-traced':
        this.takeTrace(response.requestId)?.resolve(response);
        break;
      case 'error':
        this.onRequestFailed(worker, response.failed, response.message);
        break;
    }
  }

  private onRequestFailed(worker: PoolWorker, failed: FailedRequest, message: string): void {
    switch (failed.type) {
      case 'load-scene':
        if (worker.sceneId === failed.sceneId) worker.answeredSceneId = failed.sceneId;
        if (this.job?.sceneId === failed.sceneId) this.failJob(message);
        if (this.scene?.id === failed.sceneId) this.settleReady(new Error(message));
        break;
      case 'render-tile':
        if (this.job?.id === failed.jobId) this.failJob(message);
        break;
      case 'trace-pixel':
      case 'trace-pixels':
      case 'trace-paths':
        this.takeTrace(failed.requestId)?.reject(new Error(message));
        break;
    }
  }

  /**
   * A dead or silent worker: stopped and replaced at once, its tiles handed to the next free
   * worker, its pixel traces failed (the lab asks again). After FAILURES_IN_A_ROW failures
   * with no good answer between them the job fails with `reason`, and the slot stays empty
   * until the pool is next used.
   */
  private replaceWorker(worker: PoolWorker, reason: string): void {
    const slot = this.workers.indexOf(worker);
    if (slot < 0) return;
    worker.port.terminate();
    this.workers[slot] = null;
    this.log(reason);
    for (const [requestId, trace] of this.traces) {
      if (trace.worker === worker) this.takeTrace(requestId)?.reject(new Error(reason));
    }
    const job = this.job;
    for (const tileId of worker.tiles.keys()) job?.tiles.requeue(tileId);
    worker.tiles.clear();
    if (++this.failuresInARow >= FAILURES_IN_A_ROW) {
      if (job) this.failJob(reason);
      this.settleReady(new Error(reason));
      return;
    }
    const replacement = this.spawn();
    this.workers[slot] = replacement;
    this.sendScene(replacement);
    if (job) this.pump();
  }

  /**
   * A worker whose code could not be loaded: replaced like a dead one, until START_TRIES have
   * failed in a row; then the pool stops every worker and fails all that waits, for good.
   */
  private notStarted(worker: PoolWorker, message: string): void {
    if (!this.workers.includes(worker)) return; // replaced already: its late words do not count
    if (++this.startFailuresInARow < START_TRIES) {
      // Its pixel traces wait for the worker after it (the lab asks only once per screen).
      const waiting = [...this.traces].filter(([, trace]) => trace.worker === worker);
      for (const [requestId] of waiting) this.traces.delete(requestId);
      this.replaceWorker(worker, `a render worker could not start: ${message}`);
      for (const [requestId, trace] of waiting) {
        const next = this.liveWorkers().reduce((best, w) => (w.tiles.size < best.tiles.size ? w : best));
        this.sendScene(next);
        this.post(next, trace.request, () => this.traces.set(requestId, { ...trace, worker: next }));
      }
      return;
    }
    const reason = `the render workers' code could not be loaded (${message})`;
    this.log(reason);
    this.unavailable = new RenderWorkersUnavailable(reason);
    this.failJob(reason);
    for (const requestId of [...this.traces.keys()]) this.takeTrace(requestId)?.reject(this.unavailable);
    for (const waiter of this.readyWaiters.splice(0)) waiter.reject(this.unavailable);
    for (const each of this.workers) each?.port.terminate();
    this.workers.fill(null);
    this.stopWatching();
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
    this.endJob()?.reject(this.unavailable ?? new Error(message));
  }

  /** Detaches the current job: workers drop its queued tiles and late ones are ignored. */
  private endJob(): ActiveJob | null {
    const job = this.job;
    if (!job) return null;
    this.job = null;
    for (const worker of this.workers) {
      if (worker && worker.tiles.size > 0) worker.port.post({ type: 'cancel', jobId: job.id });
      worker?.tiles.clear();
    }
    return job;
  }

  private assertOpen(): void {
    if (this.disposed) throw new Error('this render pool has been closed');
  }
}
