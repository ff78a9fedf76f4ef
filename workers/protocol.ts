/**
 * The messages between the render pool and its workers: one protocol for browser Web Workers
 * and Node worker_threads (spec §4: "same core as the browser"). Everything here is plain,
 * structured-cloneable data; the only transferable is a finished tile's pixel buffer.
 *
 * Ordering guarantee the pool relies on: a worker answers requests in the order they
 * arrive, except that queued tiles wait behind later `cancel`, `load-scene`, `trace-pixel` and
 * `trace-pixels` requests (see render-core.ts), and each queued tile keeps the scene that was current when
 * it arrived.
 */
import type { MeshLibrary } from '../src/scene/mesh-data.ts';
import type { Scene } from '../src/scene/scene.ts';
import type { LabPaths } from '../src/tracer/lab-paths.ts';
import type { PixelTrace, RayStats } from '../src/tracer/ray-tree.ts';
import type { RenderTileOptions, Tile } from '../src/tracer/tile.ts';

// ── Requests: pool → worker ──────────────────────────────────────────────────────────────

/** Replace the worker's scene (builds shapes, BVHs and lights once, for every later tile). */
export interface LoadSceneRequest {
  type: 'load-scene';
  /** The pool's version number for this scene; echoed by `scene-ready`. */
  sceneId: number;
  scene: Scene;
  /**
   * The models the scene uses that this worker has not been sent before: a worker keeps
   * every model it receives (a model's name always means the same model), so its BVH is
   * built once, not on every edit. A Map survives structured cloning.
   */
  meshes: MeshLibrary;
}

/** Render one rectangle of a job's image with the current scene. */
export interface RenderTileRequest {
  type: 'render-tile';
  jobId: number;
  /** The tile's index within its job, echoed by `tile-done`. */
  tileId: number;
  tile: Tile;
  options: RenderTileOptions;
}

/** Trace one pixel of the camera's small screen and return its ray tree (the lab). */
export interface TracePixelRequest {
  type: 'trace-pixel';
  requestId: number;
  x: number;
  y: number;
  seed: number;
  /** Add each hit's shading terms to the tree (the ray debugger); default false. */
  terms?: boolean;
}

/**
 * Trace `count` pixels of the camera's small screen from pixel index `first` (row-major over
 * camera.pixels) and return their ray trees in one message: the lab's screen in a few
 * messages instead of one per pixel (a message per pixel cost more than its trace).
 */
export interface TracePixelsRequest {
  type: 'trace-pixels';
  requestId: number;
  first: number;
  count: number;
  seed: number;
  /** Send, and record, only about this many rays, by the rule of tracer/tree-budget.ts (the lab while the learner edits); the colours are the full trace's unless `oneSample`. */
  budget?: RayBudget;
}

/** Trace one pixel in path mode and return its first `keep` sample paths (the lab's path view and debugger). */
export interface TracePathsRequest {
  type: 'trace-paths';
  requestId: number;
  x: number;
  y: number;
  seed: number;
  keep: number;
}

/**
 * A budget for a block's ray trees: about `rays` rays, all of them for screen pixel `keepPixel`
 * (y · columns + x, or null); with `oneSample`, every other pixel is traced from one of its
 * supersamples alone, uncounted (tracer/trace-within-budget.ts).
 */
export interface RayBudget {
  rays: number;
  keepPixel: number | null;
  oneSample?: boolean;
}

/** Drop the job's tiles that are still queued; the tile being rendered still finishes. */
export interface CancelRequest {
  type: 'cancel';
  jobId: number;
}

/**
 * What a browser render worker posts once its code has loaded and run, before any answer: a
 * worker that fails before it is a worker whose code could not be loaded (web-worker-port.ts).
 */
export const WORKER_STARTED = 'render-worker-started';

export type RenderRequest = LoadSceneRequest | RenderTileRequest | TracePixelRequest | TracePixelsRequest | TracePathsRequest | CancelRequest;

// ── Responses: worker → pool ─────────────────────────────────────────────────────────────

export interface SceneReadyResponse {
  type: 'scene-ready';
  sceneId: number;
  /** Time spent building the scene (BVHs and all), in milliseconds. */
  ms: number;
}

export interface TileDoneResponse {
  type: 'tile-done';
  jobId: number;
  tileId: number;
  /**
   * Linear RGB, 3 floats per pixel, row-major over the tile; its buffer is transferred. A
   * Float64Array in a progressive path pass: each pixel's running sum of its paths so far.
   */
  rgb: Float32Array<ArrayBuffer> | Float64Array<ArrayBuffer>;
  stats: RayStats;
  /** Time the worker spent on this tile, in milliseconds. */
  ms: number;
}

export interface PixelTracedResponse {
  type: 'pixel-traced';
  requestId: number;
  trace: PixelTrace;
}

export interface PathsTracedResponse {
  type: 'paths-traced';
  requestId: number;
  paths: LabPaths;
}

export interface PixelsTracedResponse {
  type: 'pixels-traced';
  requestId: number;
  /** Pixels first … first + count - 1 of the request, in that order. */
  traces: PixelTrace[];
}

/** Which request failed, so the pool can fail the right job or lab query. */
export type FailedRequest =
  | { type: 'load-scene'; sceneId: number }
  | { type: 'render-tile'; jobId: number; tileId: number }
  | { type: 'trace-pixel'; requestId: number }
  | { type: 'trace-pixels'; requestId: number }
  | { type: 'trace-paths'; requestId: number };

/** A request threw; the worker itself keeps running and answers later requests. */
export interface ErrorResponse {
  type: 'error';
  failed: FailedRequest;
  /** Text for the user, e.g. `mesh "teapot" is not loaded`. */
  message: string;
}

export type RenderResponse = SceneReadyResponse | TileDoneResponse | PixelTracedResponse | PixelsTracedResponse | PathsTracedResponse | ErrorResponse;

/** How a worker posts a response; `transfer` lists buffers to move instead of copy. */
export type PostResponse = (response: RenderResponse, transfer: ArrayBuffer[]) => void;
