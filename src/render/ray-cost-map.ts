/**
 * Where an image's rays go, learnt from the tiles already traced: the render's progress
 * counts rays, not tiles or samples, so it needs to know how many rays the tiles not traced
 * yet will take. A sample through the sky costs one ray; one through a glass ball under an
 * area light with lens samples costs hundreds. Counting samples, a render whose dear pixels
 * sit in the middle of the image crawls through its middle and races through the rest (issue
 * 37: "the full pass sat at 50–60 % for two minutes then jumped to 100 %").
 *
 * Every pass samples the whole image, so each pass teaches the next: the coarse previews
 * trace one sample per block, spread evenly, and the map keeps their rays per sample in cells
 * of a coarse grid. A later pass predicts a tile's rays from the cells it covers, with the
 * map as it was when the pass began (a snapshot), so that its predictions add up to the
 * pass's total (the pass progress relies on it).
 */
import type { Tile } from '../tracer/tile.ts';

/** At most this many cells per side: a 4096² image gets 64-pixel cells, 4096 cells in all. */
const MAX_CELLS_PER_SIDE = 64;
/** Cells no smaller than this, so that each holds a few of even the finest preview's samples (4×4 blocks). */
const MIN_CELL_SIDE = 8;

export class RayCostMap {
  readonly cellSide: number;
  readonly columns: number;
  readonly rows: number;
  private readonly rays: Float64Array;
  private readonly samples: Float64Array;
  private allRays = 0;
  private allSamples = 0;

  /** `assumedRaysPerSample`: the render estimate's, for an image of which nothing is traced yet. */
  constructor(
    readonly width: number,
    readonly height: number,
    private readonly assumedRaysPerSample: number,
  ) {
    this.cellSide = Math.max(MIN_CELL_SIDE, Math.ceil(Math.max(width, height) / MAX_CELLS_PER_SIDE));
    this.columns = Math.ceil(width / this.cellSide);
    this.rows = Math.ceil(height / this.cellSide);
    this.rays = new Float64Array(this.columns * this.rows);
    this.samples = new Float64Array(this.columns * this.rows);
  }

  /** A traced tile: its rays and samples, spread over the cells it covers by the pixels it has in each. */
  record(tile: Tile, samples: number, rays: number): void {
    const pixels = tile.width * tile.height;
    this.forEachCell(tile, (cell, overlap) => {
      this.rays[cell] += (rays * overlap) / pixels;
      this.samples[cell] += (samples * overlap) / pixels;
    });
    this.allRays += rays;
    this.allSamples += samples;
  }

  /**
   * The map as it is now, to predict one pass with: a cell's rays per sample, or where
   * nothing has been traced yet the image's mean so far (the assumed value before any tile).
   */
  snapshot(): RayCostSnapshot {
    const mean = this.allSamples > 0 ? this.allRays / this.allSamples : this.assumedRaysPerSample;
    const perSample = this.rays.map((rays, cell) => (this.samples[cell] > 0 ? rays / this.samples[cell] : mean));
    return new RayCostSnapshot(this, perSample);
  }

  /** Calls `visit` with each cell `tile` overlaps and the number of its pixels in that cell. */
  forEachCell({ x, y, width, height }: Tile, visit: (cell: number, overlap: number) => void): void {
    const side = this.cellSide;
    for (let row = Math.floor(y / side); row * side < y + height; row++) {
      const rowOverlap = Math.min(y + height, (row + 1) * side) - Math.max(y, row * side);
      for (let column = Math.floor(x / side); column * side < x + width; column++) {
        const columnOverlap = Math.min(x + width, (column + 1) * side) - Math.max(x, column * side);
        visit(row * this.columns + column, rowOverlap * columnOverlap);
      }
    }
  }
}

/** Rays per sample of every cell, frozen: predictions of one pass that add up. */
export class RayCostSnapshot {
  constructor(
    private readonly map: RayCostMap,
    private readonly perSample: Float64Array,
  ) {}

  /** The rays `tile` is expected to take at `samplesPerPixel` samples per pixel (1/block² in a preview). */
  predict(tile: Tile, samplesPerPixel: number): number {
    let rays = 0;
    this.map.forEachCell(tile, (cell, overlap) => (rays += this.perSample[cell] * overlap));
    return rays * samplesPerPixel;
  }

  /** The rays the whole image is expected to take at `samplesPerPixel`: the sum of its tiles' predictions. */
  predictImage(samplesPerPixel: number): number {
    return this.predict({ x: 0, y: 0, width: this.map.width, height: this.map.height }, samplesPerPixel);
  }
}
