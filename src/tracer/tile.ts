/** A rectangle of the image, in pixels; (0,0) is the top-left pixel. */
export interface Tile {
  x: number;
  y: number;
  width: number;
  height: number;
}

export interface RenderTileOptions {
  imageWidth: number;
  imageHeight: number;
  /** Seeds every random choice together with (pixel, sample, light). */
  seed: number;
  /**
   * Progressive preview: trace one pixel (its centre, one sample) per block×block square
   * and fill the square with it. 1 (default) is full quality.
   */
  block?: number;
  /**
   * Samples per side of each pixel at full quality (block 1): default the scene's
   * supersampling; 1 gives the render window's sharp one-sample picture. Previews always trace 1.
   */
  samplesPerPixel?: number;
  /**
   * Path mode's progressive passes (render-path-tile.ts): the pass traces paths firstPath …
   * firstPath + samplesPerPixel − 1 of each pixel, added to `pathSums`, the tile's running
   * sums of the paths before (3 per pixel, row-major over the tile).
   */
  firstPath?: number;
  pathSums?: Float64Array;
}
