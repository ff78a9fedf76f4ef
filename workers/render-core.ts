/**
 * The render worker's brain, shared by the browser Web Worker and the Node worker thread:
 * messages in, tracer calls, responses out. It imports no platform API, so both thin worker
 * files only connect it to their message port.
 */
import type { MeshData } from '../src/scene/mesh-data.ts';
import { labPaths } from '../src/tracer/lab-paths.ts';
import { emptyRayStats } from '../src/tracer/ray-tree.ts';
import { renderTile } from '../src/tracer/render-tile.ts';
import { renderPathTile } from '../src/tracer/render-path-tile.ts';
import { tracePixel, tracePixels } from '../src/tracer/trace-pixel.ts';
import { tracePixelsWithinBudget } from '../src/tracer/trace-within-budget.ts';
import { buildTracerScene, type TracerScene } from '../src/tracer/tracer-scene.ts';
import { nextTask } from './next-task.ts';
import type {
  FailedRequest,
  LoadSceneRequest,
  PostResponse,
  RenderRequest,
  RenderTileRequest,
  TracePathsRequest,
  TracePixelRequest,
  TracePixelsRequest,
} from './protocol.ts';

/** The scene that tiles and traces use: built, or why it could not be built. */
type LoadedScene = { built: true; tracer: TracerScene } | { built: false; reason: string };

/** A tile waiting for its turn, with the scene that was current when it arrived. */
interface QueuedTile {
  request: RenderTileRequest;
  scene: LoadedScene;
}

/**
 * Returns the handler for the pool's requests. Tiles are queued and rendered one per
 * event-loop task (see next-task.ts), so `cancel`, `load-scene` and pixel-trace requests
 * never wait behind more than the tile being rendered. Every error becomes an `error`
 * response; the worker keeps running.
 */
export function createRenderHandler(post: PostResponse): (request: RenderRequest) => void {
  let scene: LoadedScene = { built: false, reason: 'no scene has been loaded' };
  /** Every model received so far; their BVHs stay cached with them (see mesh-accel.ts). */
  const models = new Map<string, MeshData>();
  const queue: QueuedTile[] = [];
  let renderScheduled = false;

  function fail(failed: FailedRequest, error: unknown): void {
    post({ type: 'error', failed, message: messageOf(error) }, []);
  }

  function tracerOf(loaded: LoadedScene): TracerScene {
    if (!loaded.built) throw new Error(loaded.reason);
    return loaded.tracer;
  }

  function loadScene({ sceneId, scene: sceneFile, meshes }: LoadSceneRequest): void {
    const start = performance.now();
    try {
      for (const [name, mesh] of meshes) models.set(name, mesh);
      scene = { built: true, tracer: buildTracerScene(sceneFile, models) };
      post({ type: 'scene-ready', sceneId, ms: performance.now() - start }, []);
    } catch (error) {
      scene = { built: false, reason: messageOf(error) };
      fail({ type: 'load-scene', sceneId }, error);
    }
  }

  function traceNow({ requestId, x, y, seed, terms }: TracePixelRequest): void {
    try {
      post({ type: 'pixel-traced', requestId, trace: tracePixel(tracerOf(scene), x, y, seed, { terms }) }, []);
    } catch (error) {
      fail({ type: 'trace-pixel', requestId }, error);
    }
  }

  function traceManyNow({ requestId, first, count, seed, budget }: TracePixelsRequest): void {
    try {
      const tracer = tracerOf(scene);
      const [columns, rows] = tracer.source.camera.pixels;
      if (!Number.isInteger(first) || !Number.isInteger(count) || first < 0 || count < 1 || first + count > columns * rows) {
        throw new RangeError(`pixels ${first} to ${first + count - 1} are not on the ${columns}×${rows} screen`);
      }
      // A block's trees are copied into the page's memory as objects, a cost per ray on its main thread;
      // with a budget, only the trees it keeps are recorded at all.
      const traces = budget
        ? tracePixelsWithinBudget(
            tracer,
            first,
            count,
            seed,
            budget.rays,
            budget.keepPixel === null ? null : budget.keepPixel - first,
            budget.oneSample === true,
          )
        : tracePixels(tracer, first, count, seed);
      post({ type: 'pixels-traced', requestId, traces }, []);
    } catch (error) {
      fail({ type: 'trace-pixels', requestId }, error);
    }
  }

  function tracePathsNow({ requestId, x, y, seed, keep }: TracePathsRequest): void {
    try {
      post({ type: 'paths-traced', requestId, paths: labPaths(tracerOf(scene), x, y, seed, keep) }, []);
    } catch (error) {
      fail({ type: 'trace-paths', requestId }, error);
    }
  }

  function scheduleRender(): void {
    if (renderScheduled || queue.length === 0) return;
    renderScheduled = true;
    nextTask(renderNextTile);
  }

  function renderNextTile(): void {
    renderScheduled = false;
    const next = queue.shift();
    if (next) {
      const { jobId, tileId, tile, options } = next.request;
      try {
        const stats = emptyRayStats();
        const start = performance.now();
        const tracer = tracerOf(next.scene);
        // A progressive path pass carries each pixel's sum on (render-path-tile.ts), in a fresh buffer of its own.
        const rgb = options.pathSums ? renderPathTile(tracer, tile, options, stats) : transferable(renderTile(tracer, tile, options, stats));
        post({ type: 'tile-done', jobId, tileId, rgb, stats, ms: performance.now() - start }, [rgb.buffer]);
      } catch (error) {
        fail({ type: 'render-tile', jobId, tileId }, error);
      }
    }
    scheduleRender();
  }

  return (request) => {
    switch (request.type) {
      case 'load-scene':
        loadScene(request);
        break;
      case 'render-tile':
        queue.push({ request, scene });
        scheduleRender();
        break;
      case 'trace-pixel':
        traceNow(request);
        break;
      case 'trace-pixels':
        traceManyNow(request);
        break;
      case 'trace-paths':
        tracePathsNow(request);
        break;
      case 'cancel':
        for (let i = queue.length - 1; i >= 0; i--) {
          if (queue[i].request.jobId === request.jobId) queue.splice(i, 1);
        }
        break;
    }
  };
}

function messageOf(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

/**
 * The tile's pixels in a buffer of their own that can be transferred. renderTile allocates a
 * fresh array, so this is a type-level check that costs nothing; anything else is copied.
 */
function transferable(rgb: Float32Array): Float32Array<ArrayBuffer> {
  const ownsBuffer = (array: Float32Array): array is Float32Array<ArrayBuffer> =>
    array.buffer instanceof ArrayBuffer && array.byteOffset === 0 && array.byteLength === array.buffer.byteLength;
  return ownsBuffer(rgb) ? rgb : new Float32Array(rgb);
}
