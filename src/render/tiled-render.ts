/**
 * One render split into passes of tiles (see render-passes.ts). It decides which tile goes
 * next, pastes finished tiles into the image and reports progress; the pool does the
 * messaging. Tiles are computed from their number, never listed, so a huge image with
 * tiny tiles costs no memory up front.
 */
import { addRayStats, emptyRayStats, type RayStats } from '../tracer/ray-tree.ts';
import type { Tile } from '../tracer/tile.ts';
import { tracedSamples, type RenderPass } from './render-passes.ts';
import type { RenderImage, RenderOptions, RenderProgress } from './render-job.ts';

/** Progress callbacks at most this often (besides a pass's first and last tile): enough for a smooth bar, cheap for the UI thread. */
const PROGRESS_INTERVAL_MS = 50;

interface PlannedPass extends RenderPass {
  columns: number;
  /** Number of tiles. */
  count: number;
  /** The tile id of its first tile: ids run on across passes. */
  firstId: number;
  /** Samples the whole pass traces: its work, for progress. */
  samples: number;
}

/** A tile handed to a worker: `tileId` comes back with its pixels. */
export interface TileAssignment {
  tileId: number;
  tile: Tile;
  block: number;
  samplesPerSide: number;
}

export class TiledRender {
  readonly image: RenderImage;
  /** Rays of the full-quality pass only. */
  readonly stats = emptyRayStats();
  slowestTileMs = 0;

  private readonly passes: PlannedPass[] = [];
  private pass = 0;
  /** Tiles of the current pass handed out and not back yet, by id. */
  private readonly outstanding = new Map<number, TileAssignment>();
  /** Tiles whose worker died: handed out again before new ones. */
  private readonly returned: TileAssignment[] = [];
  /** Tiles of the current pass handed out, and finished. */
  private taken = 0;
  private finishedInPass = 0;
  /** Samples of the current pass traced so far. */
  private samplesDone = 0;
  private lastProgressAt = -Infinity;
  /** Rows pasted since `takeChangedRows` last asked: [from, to), empty when from ≥ to. */
  private changedFrom = Infinity;
  private changedTo = 0;

  constructor(
    width: number,
    height: number,
    passes: RenderPass[],
    private readonly callbacks: Pick<RenderOptions, 'onPreview' | 'onProgress'>,
  ) {
    this.image = { width, height, rgb: new Float32Array(width * height * 3) };
    let firstId = 0;
    for (const pass of passes) {
      const columns = Math.ceil(width / pass.tileWidth);
      const count = columns * Math.ceil(height / pass.tileHeight);
      // Tiles start at multiples of the block, so their samples add up to the whole image's.
      this.passes.push({ ...pass, columns, count, firstId, samples: tracedSamples({ x: 0, y: 0, width, height }, pass) });
      firstId += count;
    }
  }

  get finished(): boolean {
    return this.pass === this.passes.length;
  }

  /** The next tile of the current pass, or null until the pass is complete (a coarse pass
   *  must not paint over finer tiles that finished before it). */
  takeTile(): TileAssignment | null {
    const pass = this.passes[this.pass];
    if (!pass) return null;
    let next = this.returned.shift();
    if (!next) {
      if (this.taken === pass.count) return null;
      const index = this.taken++;
      next = { tileId: pass.firstId + index, tile: this.tileOf(pass, index), block: pass.block, samplesPerSide: pass.samplesPerSide };
    }
    this.outstanding.set(next.tileId, next);
    return next;
  }

  /** A tile handed out whose worker died: it goes to the next worker that asks. */
  requeue(tileId: number): void {
    const tile = this.outstanding.get(tileId);
    if (!tile) return;
    this.outstanding.delete(tileId);
    this.returned.push(tile);
  }

  /** Why a finished tile cannot be pasted (not handed out or already back, wrong pixel count), or null when it can. */
  problemWith(tileId: number, rgb: Float32Array): string | null {
    const tile = this.outstanding.get(tileId)?.tile;
    if (!tile) return `tile ${tileId} is not one being rendered`;
    const expected = tile.width * tile.height * 3;
    return rgb.length === expected ? null : `tile ${tileId} came back with ${rgb.length} values instead of ${expected}`;
  }

  /**
   * Pastes a finished tile of the current pass into the image, then reports progress and,
   * when a pass before the final one completes, the preview. The state is updated before the callbacks
   * run, so a callback that throws leaves the render consistent. The caller checks the tile
   * with `problemWith` first.
   */
  accept(tileId: number, rgb: Float32Array, stats: RayStats, ms: number): void {
    const pass = this.passes[this.pass];
    const tile = this.tileOf(pass, tileId - pass.firstId);
    this.outstanding.delete(tileId);
    this.paste(tile, rgb);
    this.slowestTileMs = Math.max(this.slowestTileMs, ms);
    if (pass.kind === 'final') addRayStats(this.stats, stats);
    this.samplesDone += tracedSamples(tile, pass);
    const progress: RenderProgress = { phase: pass.kind, pass: this.pass + 1, passes: this.passes.length, done: this.samplesDone, total: pass.samples };
    const first = ++this.finishedInPass === 1;
    const passComplete = this.finishedInPass === pass.count;
    if (passComplete) {
      this.pass++;
      this.taken = 0;
      this.finishedInPass = 0;
      this.samplesDone = 0;
    }

    this.reportProgress(progress, first || passComplete);
    if (passComplete && pass.kind !== 'final') this.callbacks.onPreview?.(this.image);
  }

  /** The rows pasted since the last call, [from, to), or null: a painter redraws only those. */
  takeChangedRows(): [number, number] | null {
    const rows: [number, number] | null = this.changedFrom < this.changedTo ? [this.changedFrom, this.changedTo] : null;
    this.changedFrom = Infinity;
    this.changedTo = 0;
    return rows;
  }

  /** Tiles run row by row, top to bottom; those on the right and bottom edges are cut to fit. */
  private tileOf({ tileWidth, tileHeight, columns }: PlannedPass, index: number): Tile {
    const x = (index % columns) * tileWidth;
    const y = Math.floor(index / columns) * tileHeight;
    return { x, y, width: Math.min(tileWidth, this.image.width - x), height: Math.min(tileHeight, this.image.height - y) };
  }

  private paste({ x, y, width, height }: Tile, rgb: Float32Array): void {
    this.changedFrom = Math.min(this.changedFrom, y);
    this.changedTo = Math.max(this.changedTo, y + height);
    // A tile of whole rows (a preview's) is one contiguous run of the image.
    if (x === 0 && width === this.image.width) {
      this.image.rgb.set(rgb, y * width * 3);
      return;
    }
    const rowLength = width * 3;
    for (let row = 0; row < height; row++) {
      const from = row * rowLength;
      this.image.rgb.set(rgb.subarray(from, from + rowLength), ((y + row) * this.image.width + x) * 3);
    }
  }

  /** `always`: a pass's first or last tile, so each pass shows at once and ends at 100 %. */
  private reportProgress(progress: RenderProgress, always: boolean): void {
    const now = performance.now();
    if (!always && now - this.lastProgressAt < PROGRESS_INTERVAL_MS) return;
    this.lastProgressAt = now;
    this.callbacks.onProgress?.(progress);
  }
}
