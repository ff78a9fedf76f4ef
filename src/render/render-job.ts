/**
 * The public shape of a render: what `RenderPool.render` takes, hands back and resolves with.
 * The UI shows `image` while it fills in and the finished result at the end.
 */
import type { RayStats } from '../tracer/ray-tree.ts';

/** Any fixed seed works; one default everywhere makes renders and ray trees repeatable. */
export const DEFAULT_SEED = 0;

/** Linear RGB, 3 floats per pixel in 0..1, row-major, (0,0) top-left. */
export interface RenderImage {
  width: number;
  height: number;
  rgb: Float32Array;
}

export interface RenderProgress {
  /** 'preview' counts the tiles of all coarse passes together; 'full' the full-quality tiles. */
  phase: 'preview' | 'full';
  done: number;
  total: number;
}

export interface RenderOptions {
  /** Default: scene.settings.imageSize. */
  width?: number;
  height?: number;
  /** Default: DEFAULT_SEED. */
  seed?: number;
  /** Coarse passes before full quality (default true); `rt render` turns them off. */
  preview?: boolean;
  /** After each coarse pass, with the whole image filled in blocks (the job's live `image`). */
  onPreview?: (image: RenderImage) => void;
  /** At most every 50 ms per phase, and always when a phase completes. */
  onProgress?: (progress: RenderProgress) => void;
}

export interface FinishedRender extends RenderImage {
  cancelled: false;
  /** Rays of the full-quality pass (preview rays are not counted). */
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
  /** The picture so far: coarse blocks first, then full-quality tiles as they arrive. */
  readonly image: RenderImage;
  /** Resolves when finished or cancelled; rejects with an Error whose message the UI can show. */
  readonly done: Promise<RenderResult>;
  /** Stops the job: no more tiles are sent and late tiles are ignored. Safe to call twice. */
  cancel(): void;
}
