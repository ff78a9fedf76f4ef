import { describe, expect, it } from 'vitest';
import type { PreviewImage, RenderImage } from '../../../../src/render/render-job.ts';
import { PartialPicture } from '../../../../src/ui/lab/render-window/partial-picture.ts';

/** A 5 × 3 image whose pixel i has the red value i + 1 (0 is "not traced": the job's image starts black). */
function tracedImage(): RenderImage {
  const rgb = new Float32Array(5 * 3 * 3);
  for (let i = 0; i < 15; i++) rgb[i * 3] = i + 1;
  return { width: 5, height: 3, rgb };
}

/** A preview of the 5 × 3 image with 2 × 2 blocks: 2 × 1 preview pixels whose red values are 100 and 200 (edges cover the rest). */
const PREVIEW: PreviewImage = { width: 2, height: 1, block: 2, rgb: new Float32Array([100, 0, 0, 200, 0, 0]) };

function reds(image: RenderImage): number[] {
  return Array.from({ length: image.width * image.height }, (_, i) => image.rgb[i * 3]);
}

describe('PartialPicture', () => {
  it('has nothing to save before the first preview or tile', () => {
    const partial = new PartialPicture();
    expect(partial.traced).toBe(false);
    expect(partial.picture(tracedImage())).toBeNull();
  });

  it('fills every pixel from the last preview, each preview pixel covering its block and the edges', () => {
    const partial = new PartialPicture();
    partial.note(tracedImage(), { preview: { image: PREVIEW, rows: [0, 1] }, tiles: [] });
    // Rows of 5: columns 0-1 in block 0; columns 2-4 in the last block (the edge).
    expect(reds(partial.picture(tracedImage())!)).toEqual([100, 100, 200, 200, 200, 100, 100, 200, 200, 200, 100, 100, 200, 200, 200]);
  });

  it('takes the traced pixels of pasted tiles over the preview, and keeps the preview elsewhere', () => {
    const partial = new PartialPicture();
    const image = tracedImage();
    partial.note(image, { preview: { image: PREVIEW, rows: [0, 1] }, tiles: [] });
    partial.note(image, { preview: null, tiles: [{ x: 1, y: 1, width: 2, height: 2 }] });
    expect(reds(partial.picture(image)!)).toEqual([100, 100, 200, 200, 200, 100, 7, 8, 200, 200, 100, 12, 13, 200, 200]);
  });

  it('leaves untraced pixels black when there was no preview, and starts afresh after reset', () => {
    const partial = new PartialPicture();
    const image = tracedImage();
    partial.note(image, { preview: null, tiles: [{ x: 0, y: 0, width: 5, height: 1 }] });
    expect(reds(partial.picture(image)!)).toEqual([1, 2, 3, 4, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    expect(partial.traced).toBe(true);
    partial.reset();
    expect(partial.traced).toBe(false);
    expect(partial.picture(image)).toBeNull();
  });

  it('copies the pixels, so the job pasting on does not change a saved picture', () => {
    const partial = new PartialPicture();
    const image = tracedImage();
    partial.note(image, { preview: null, tiles: [{ x: 0, y: 0, width: 1, height: 1 }] });
    const picture = partial.picture(image)!;
    image.rgb[0] = 99;
    expect(picture.rgb[0]).toBe(1);
  });
});
