import type { PreviewImage, RenderChanges, RenderImage } from '../../../render/render-job.ts';

/**
 * What a running render has shown so far, kept so that a cancelled render can still be
 * saved as the learner saw it: the job's image where its tiles have been pasted, and the
 * last coarse preview (each of its pixels filling its block×block square, as the window
 * draws it) everywhere else. Pure bookkeeping of the changes the painter is given.
 */
export class PartialPicture {
  /** The last preview pass's picture, or null before the first one. */
  private preview: PreviewImage | null = null;
  /** 1 for each image pixel a tile of the job has been pasted into (row-major), null before the first tile. */
  private pasted: Uint8Array | null = null;

  /** A new render starts: nothing of it is traced yet. */
  reset(): void {
    this.preview = null;
    this.pasted = null;
  }

  /** Whether anything was traced: a preview or a tile. */
  get traced(): boolean {
    return this.preview !== null || this.pasted !== null;
  }

  /** The changes of `image` the painter was just given. */
  note(image: RenderImage, changes: RenderChanges): void {
    if (changes.preview) this.preview = changes.preview.image;
    if (changes.tiles.length === 0) return;
    const pasted = (this.pasted ??= new Uint8Array(image.width * image.height));
    for (const tile of changes.tiles) {
      for (let y = tile.y; y < tile.y + tile.height; y++) pasted.fill(1, y * image.width + tile.x, y * image.width + tile.x + tile.width);
    }
  }

  /** The picture so far at the image's full size (a new copy), or null when nothing was traced yet. */
  picture(image: RenderImage): RenderImage | null {
    const { preview, pasted } = this;
    if (!preview && !pasted) return null;
    const { width, height } = image;
    const rgb = new Float32Array(width * height * 3);
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const at = y * width + x;
        if (pasted?.[at]) {
          rgb.set(image.rgb.subarray(at * 3, at * 3 + 3), at * 3);
        } else if (preview) {
          // The last column and row of a preview cover what is left at the edges (render-job.ts).
          const px = Math.min(Math.floor(x / preview.block), preview.width - 1);
          const py = Math.min(Math.floor(y / preview.block), preview.height - 1);
          const from = (py * preview.width + px) * 3;
          rgb.set(preview.rgb.subarray(from, from + 3), at * 3);
        }
      }
    }
    return { width, height, rgb };
  }
}
