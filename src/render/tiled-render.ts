/**
 * One render split into passes of tiles (see render-passes.ts). It decides which tile goes
 * next, pastes finished tiles into the image and reports progress; the pool does the
 * messaging. Tiles are computed from their number, never listed, so a huge image with
 * tiny tiles costs no memory up front.
 *
 * A preview pass's tiles are pasted into a picture of its own, one pixel per block (a
 * worker fills each block of its tile with the block's one sample, so every block×block-th
 * value is read): copying those full-resolution tiles into the image cost the page 1.1–1.7 s
 * of the first 5 s of a 4096² render, and its painter as much again, while a 4×4 preview
 * is 1/16 of that and the window draws it scaled up.
 */
import { addRayStats, emptyRayStats, type RayStats } from '../tracer/ray-tree.ts';
import type { Tile } from '../tracer/tile.ts';
import { tracedSamples, type RenderPass } from './render-passes.ts';
import { RenderWork } from './render-work.ts';
import type { PathCount, PreviewImage, RenderChanges, RenderImage, RenderOptions, RenderProgress } from './render-job.ts';

/** Tiles listed for the painter at most; past this many, the rows they span are given as one full-width tile. */
const MAX_CHANGED_TILES = 256;

/** Progress callbacks at most this often (besides a pass's first and last tile): enough for a smooth bar, cheap for the UI thread. */
const PROGRESS_INTERVAL_MS = 50;

interface PlannedPass extends RenderPass {
  columns: number;
  /** Number of tiles. */
  count: number;
  /** The tile id of its first tile: ids run on across passes. */
  firstId: number;
}

/** A tile handed to a worker: `tileId` comes back with its pixels. */
export interface TileAssignment {
  tileId: number;
  tile: Tile;
  block: number;
  samplesPerPixel: number;
  /** A progressive path pass's first path (path-passes.ts): the tile carries its pixels' sums on. */
  firstPath?: number;
}

export class TiledRender {
  readonly image: RenderImage;
  /** Rays of the full-quality pass only. */
  readonly stats = emptyRayStats();
  slowestTileMs = 0;
  /** The progress in rays (render-work.ts). */
  private readonly work: RenderWork;

  private readonly passes: PlannedPass[] = [];
  private pass = 0;
  /** Tiles of the current pass handed out and not back yet, by id. */
  private readonly outstanding = new Map<number, TileAssignment>();
  /** Tiles whose worker died: handed out again before new ones. */
  private readonly returned: TileAssignment[] = [];
  /** Tiles of the current pass handed out, and finished. */
  private taken = 0;
  private finishedInPass = 0;
  private lastProgressAt = -Infinity;
  /** The running preview pass's picture (null in the other passes). */
  private preview: PreviewImage | null = null;
  /**
   * The preview pasted into since `takeChanges` last asked (it stays after its pass ends),
   * and its rows pasted: [from, to), empty when from ≥ to.
   */
  private changedPreview: PreviewImage | null = null;
  private previewFrom = Infinity;
  private previewTo = 0;
  /** Tiles of the image pasted since `takeChanges` last asked. */
  private changedTiles: Tile[] = [];
  /** Whether changedTiles is the one full-width tile of many tiles' rows. */
  private changedAsRows = false;
  /**
   * Path mode's progressive passes: each pixel's sum of its paths so far, in 64-bit floats as
   * the tracer sums them (render-path-tile.ts); null for a render without them.
   */
  private readonly sums: Float64Array | null;

  /** `assumedRaysPerSample`: the render estimate's rays per sample, to predict the first pass's progress by. */
  constructor(
    width: number,
    height: number,
    passes: RenderPass[],
    private readonly callbacks: Pick<RenderOptions, 'onPreview' | 'onProgress'>,
    assumedRaysPerSample = 1,
  ) {
    this.image = { width, height, rgb: new Float32Array(width * height * 3) };
    let firstId = 0;
    for (const pass of passes) {
      const columns = Math.ceil(width / pass.tileWidth);
      const count = columns * Math.ceil(height / pass.tileHeight);
      this.passes.push({ ...pass, columns, count, firstId });
      firstId += count;
    }
    this.work = new RenderWork(width, height, passes, assumedRaysPerSample);
    this.sums = passes.some((pass) => pass.firstPath !== undefined) ? new Float64Array(width * height * 3) : null;
    this.startPass();
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
      next = { tileId: pass.firstId + index, tile: this.tileOf(pass, index), block: pass.block, samplesPerPixel: pass.samplesPerPixel };
      if (pass.firstPath !== undefined) next.firstPath = pass.firstPath;
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

  /** The running sums of a progressive path pass's tile (path-passes.ts), copied for its worker to carry on. */
  sumsOf({ x, y, width, height }: Tile): Float64Array {
    const sums = new Float64Array(width * height * 3);
    if (!this.sums) return sums;
    for (let row = 0; row < height; row++) {
      const from = ((y + row) * this.image.width + x) * 3;
      sums.set(this.sums.subarray(from, from + width * 3), row * width * 3);
    }
    return sums;
  }

  /**
   * Why a finished tile cannot be pasted (not handed out or already back, wrong pixel count,
   * 32-bit pixels where a progressive path pass wants 64-bit sums or the other way round),
   * or null when it can.
   */
  problemWith(tileId: number, rgb: Float32Array | Float64Array): string | null {
    const assignment = this.outstanding.get(tileId);
    if (!assignment) return `tile ${tileId} is not one being rendered`;
    const { tile, firstPath } = assignment;
    const expected = tile.width * tile.height * 3;
    if (rgb.length !== expected) return `tile ${tileId} came back with ${rgb.length} values instead of ${expected}`;
    if ((firstPath !== undefined) !== rgb instanceof Float64Array)
      return `tile ${tileId} came back with ${firstPath === undefined ? 'sums of paths' : 'pixels'} instead of ${firstPath === undefined ? 'pixels' : 'sums of paths'}`;
    return null;
  }

  /**
   * Pastes a finished tile of the current pass into the image, then reports progress and,
   * when a pass before the final one completes, the preview. The state is updated before the callbacks
   * run, so a callback that throws leaves the render consistent. The caller checks the tile
   * with `problemWith` first.
   */
  accept(tileId: number, rgb: Float32Array | Float64Array, stats: RayStats, ms: number): void {
    const pass = this.passes[this.pass];
    const tile = this.tileOf(pass, tileId - pass.firstId);
    this.outstanding.delete(tileId);
    const preview = this.preview;
    if (rgb instanceof Float64Array) this.addPaths(tile, rgb, (pass.firstPath ?? 0) + pass.samplesPerPixel);
    else if (preview) this.pastePreview(preview, tile, rgb);
    else this.paste(tile, rgb);
    this.slowestTileMs = Math.max(this.slowestTileMs, ms);
    if (pass.kind === 'final') addRayStats(this.stats, stats);
    const first = ++this.finishedInPass === 1;
    const passComplete = this.finishedInPass === pass.count;
    const work = this.work.tileBack(tile, tracedSamples(tile, pass), stats, passComplete);
    const progress: RenderProgress = {
      phase: pass.kind,
      pass: this.pass + 1,
      passes: this.passes.length,
      ...work,
      paths: this.pathCount(pass, work, passComplete),
    };
    if (passComplete) {
      this.pass++;
      this.taken = 0;
      this.finishedInPass = 0;
      this.work.startPass(this.pass);
      this.startPass();
    }

    this.reportProgress(progress, first || passComplete);
    if (passComplete && pass.kind !== 'final') this.callbacks.onPreview?.(preview ?? this.image);
  }

  /** What was pasted since the last call, or null: a painter redraws only that. */
  takeChanges(): RenderChanges | null {
    const preview = this.changedPreview;
    const changes: RenderChanges = {
      preview: preview && this.previewFrom < this.previewTo ? { image: preview, rows: [this.previewFrom, this.previewTo] } : null,
      tiles: this.changedTiles,
    };
    this.changedPreview = null;
    this.previewFrom = Infinity;
    this.previewTo = 0;
    this.changedTiles = [];
    this.changedAsRows = false;
    return changes.preview || changes.tiles.length > 0 ? changes : null;
  }

  /**
   * A preview pass gets a picture of its own, starting as the coarser one before it scaled
   * up (so its rows not traced yet show that, not black); the others paste into the image.
   */
  private startPass(): void {
    const pass = this.passes[this.pass];
    const coarser = this.preview;
    if (pass?.kind !== 'preview') {
      this.preview = null;
      return;
    }
    const width = Math.ceil(this.image.width / pass.block);
    const height = Math.ceil(this.image.height / pass.block);
    const preview: PreviewImage = { width, height, block: pass.block, rgb: new Float32Array(width * height * 3) };
    if (coarser) {
      const ratio = coarser.block / pass.block;
      const [to, from] = [preview.rgb, coarser.rgb];
      for (let y = 0, i = 0; y < height; y++) {
        const row = Math.floor(y / ratio) * coarser.width;
        for (let x = 0; x < width; x++, i += 3) {
          const at = (row + Math.floor(x / ratio)) * 3;
          to[i] = from[at];
          to[i + 1] = from[at + 1];
          to[i + 2] = from[at + 2];
        }
      }
      // The coarser one's rows not yet asked for are now these rows of this one.
      if (this.changedPreview === coarser && this.previewFrom < this.previewTo) {
        [this.changedPreview, this.previewFrom, this.previewTo] = [preview, this.previewFrom * ratio, Math.min(height, this.previewTo * ratio)];
      }
    }
    this.preview = preview;
  }

  /** A preview tile's first value of every block (the worker repeats it over the block). */
  private pastePreview(preview: PreviewImage, { x, y, width, height }: Tile, rgb: Float32Array): void {
    const { block } = preview;
    const [left, top] = [x / block, y / block];
    const [columns, rows] = [Math.ceil(width / block), Math.ceil(height / block)];
    if (this.changedPreview !== preview) [this.changedPreview, this.previewFrom, this.previewTo] = [preview, Infinity, 0];
    this.previewFrom = Math.min(this.previewFrom, top);
    this.previewTo = Math.max(this.previewTo, top + rows);
    for (let row = 0; row < rows; row++) {
      for (let column = 0; column < columns; column++) {
        const from = (row * block * width + column * block) * 3;
        const to = ((top + row) * preview.width + left + column) * 3;
        preview.rgb[to] = rgb[from];
        preview.rgb[to + 1] = rgb[from + 1];
        preview.rgb[to + 2] = rgb[from + 2];
      }
    }
  }

  /**
   * A progressive path pass's tile: its pixels' new sums kept, and shown divided by the paths
   * they hold, as `v · (1/paths)`: three.js's divideScalar, which a one-pass render's pixel
   * ends with (render-path-pixel.ts), so the last pass shows the same bits.
   */
  private addPaths(tile: Tile, sums: Float64Array, paths: number): void {
    const { x, y, width, height } = tile;
    const scale = 1 / paths;
    this.noteChanged(tile);
    for (let row = 0; row < height; row++) {
      let at = ((y + row) * this.image.width + x) * 3;
      for (let i = row * width * 3, end = i + width * 3; i < end; i++, at++) {
        this.sums![at] = sums[i];
        this.image.rgb[at] = sums[i] * scale;
      }
    }
  }

  /** The paths per pixel done after this tile of a progressive path pass; null in the other passes. */
  private pathCount(pass: RenderPass, work: { done: number; total: number }, passComplete: boolean): PathCount | null {
    if (pass.firstPath === undefined) return null;
    const total = this.passes[this.passes.length - 1]!;
    const paths = (total.firstPath ?? 0) + total.samplesPerPixel;
    const done = pass.firstPath + (passComplete ? pass.samplesPerPixel : 0);
    const share = passComplete ? 1 : work.done / Math.max(work.total, Number.MIN_VALUE);
    return { done, total: paths, fraction: (pass.firstPath + pass.samplesPerPixel * share) / paths };
  }

  /** Tiles run row by row, top to bottom; those on the right and bottom edges are cut to fit. */
  private tileOf({ tileWidth, tileHeight, columns }: PlannedPass, index: number): Tile {
    const x = (index % columns) * tileWidth;
    const y = Math.floor(index / columns) * tileHeight;
    return { x, y, width: Math.min(tileWidth, this.image.width - x), height: Math.min(tileHeight, this.image.height - y) };
  }

  private paste(tile: Tile, rgb: Float32Array): void {
    const { x, y, width, height } = tile;
    this.noteChanged(tile);
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

  /** Lists a pasted tile for the painter; past MAX_CHANGED_TILES, the rows of them all as one tile. */
  private noteChanged(tile: Tile): void {
    const tiles = this.changedTiles;
    if (tiles.length < MAX_CHANGED_TILES && !this.changedAsRows) {
      tiles.push(tile);
      return;
    }
    let [from, to] = [tile.y, tile.y + tile.height];
    for (const { y, height } of tiles) [from, to] = [Math.min(from, y), Math.max(to, y + height)];
    this.changedTiles = [{ x: 0, y: from, width: this.image.width, height: to - from }];
    this.changedAsRows = true;
  }

  /** `always`: a pass's first or last tile, so each pass shows at once and ends at 100 %. */
  private reportProgress(progress: RenderProgress, always: boolean): void {
    const now = performance.now();
    if (!always && now - this.lastProgressAt < PROGRESS_INTERVAL_MS) return;
    this.lastProgressAt = now;
    this.callbacks.onProgress?.(progress);
  }
}
