/**
 * The public shape of a render: what `RenderPool.render` takes, hands back and resolves with.
 * The UI shows `image` while it fills in and the finished result at the end.
 */
import type { RayStats } from '../tracer/ray-tree.ts';
import type { Tile } from '../tracer/tile.ts';
import type { PassKind } from './render-passes.ts';

/** Any fixed seed works; one default everywhere makes renders and ray trees repeatable. */
export const DEFAULT_SEED = 0;

/** Linear RGB, 3 floats per pixel in 0..1, row-major, (0,0) top-left. */
export interface RenderImage {
  width: number;
  height: number;
  rgb: Float32Array;
}

/**
 * A coarse preview at its own resolution: one pixel per block×block square of the image
 * (the last column and row cover what is left at the edges). The window draws it scaled up.
 */
export interface PreviewImage extends RenderImage {
  block: number;
}

/** What a painter must redraw since it last asked (RenderJob.changes). */
export interface RenderChanges {
  /** The running preview pass's picture and its rows [from, to) that changed, in its own pixels. */
  preview: { image: PreviewImage; rows: [number, number] } | null;
  /** Rectangles of the full-resolution image pasted since (tiles, or whole rows when many). */
  tiles: Tile[];
}

/** Where a render is: which of its passes (render-passes.ts), and how far into it. */
export interface RenderProgress {
  /** What the current pass makes: coarse blocks, a sharp one-sample picture, or the image. */
  phase: PassKind;
  /** The pass's number, 1 to `passes`. */
  pass: number;
  passes: number;
  /**
   * Rays of this pass traced, and those plus the rays its other tiles are predicted to take
   * (render-work.ts): a sample through glass under an area light costs a hundred times one
   * through the sky, so counting samples or tiles would crawl and then jump.
   */
  done: number;
  total: number;
  /** Seconds the render has left at the final pass's rate so far (render-work.ts); null before the final pass's first seconds. */
  secondsLeft: number | null;
  /** In path mode's progressive passes (path-passes.ts), how many paths per pixel are done; null in the other passes. */
  paths: PathCount | null;
}

/** Paths per pixel of a progressive path render: "37 of 256 paths per pixel". */
export interface PathCount {
  /** Paths every pixel of the picture on show holds (a pass's tiles not back yet still show the paths before it). */
  done: number;
  /** N, the scene's pathSamples. */
  total: number;
  /** The render's share done, 0..1: the passes done and the pass under way's share of its rays. */
  fraction: number;
}

export interface RenderOptions {
  /** Default: scene.settings.imageSize. */
  width?: number;
  height?: number;
  /** Default: DEFAULT_SEED. */
  seed?: number;
  /** Coarse passes and a sharp one-sample pass before full quality (default true); `rt render` turns them off. */
  preview?: boolean;
  /** One pass of one sample per pixel and nothing else (default false): the time estimate's probe (render-probe.ts). */
  oneSample?: boolean;
  /**
   * After each pass before the final one: a preview pass's picture at its own resolution,
   * or (after the sharp pass) the job's live `image`, filled in whole.
   */
  onPreview?: (image: RenderImage | PreviewImage) => void;
  /** After the first tile, then at most every 50 ms, and always when a pass completes. */
  onProgress?: (progress: RenderProgress) => void;
}

export interface FinishedRender extends RenderImage {
  cancelled: false;
  /** Rays of the full-quality pass (preview and sharp-pass rays are not counted). */
  stats: RayStats;
  /** Wall-clock time from `render()` to the last tile. */
  ms: number;
  workers: number;
  /** The longest single tile, in ms: it bounds how fast a new render can take over. */
  slowestTileMs: number;
  /** Longest scene build (BVHs etc.) of a worker during this job; 0 when already loaded. */
  sceneMs: number;
}

/**
 * A cancelled job resolves (it does not reject): being replaced by a newer render is normal,
 * not an error, and an ignored promise must not become an unhandled rejection.
 */
export interface CancelledRender {
  cancelled: true;
}

export type RenderResult = FinishedRender | CancelledRender;

export interface RenderJob {
  /**
   * The full-resolution picture so far: black until the first pass at one sample per pixel
   * (the previews are kept apart, at their own resolution: `changes`), then its tiles and
   * the final ones as they arrive.
   */
  readonly image: RenderImage;
  /** Resolves when finished or cancelled; rejects with an Error whose message the UI can show. */
  readonly done: Promise<RenderResult>;
  /** Stops the job: no more tiles are sent and late tiles are ignored. Safe to call twice. */
  cancel(): void;
  /**
   * What changed since the last call, or null: a painter redraws the preview's new rows
   * scaled up and the tiles of `image`, not the whole image (a 4096² image is 16 M pixels to
   * quantize).
   */
  changes(): RenderChanges | null;
}
