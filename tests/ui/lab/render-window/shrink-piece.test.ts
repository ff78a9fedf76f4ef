import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { RenderImage } from '../../../../src/render/render-job.ts';
import { shrinkPiece } from '../../../../src/ui/lab/render-window/shrink-piece.ts';
import { PLAIN_QUANTIZATION, type Quantization } from '../../../../src/tracer/quantize.ts';
import { linearToSrgb } from '../../../../src/tracer/srgb.ts';

const PLAIN: Quantization = PLAIN_QUANTIZATION;
const DITHERED: Quantization = { ...PLAIN_QUANTIZATION, dithering: true };

/** Node has no ImageData: a stand-in with its (data, width, height) constructor. */
class FakeImageData {
  constructor(
    readonly data: Uint8ClampedArray,
    readonly width: number,
    readonly height: number,
  ) {}
}

beforeEach(() => vi.stubGlobal('ImageData', FakeImageData));
afterEach(() => vi.unstubAllGlobals());

/** An image whose pixel (x, y) is grey level `level(x, y)` (0–1). */
function image(width: number, height: number, level: (x: number, y: number) => number): RenderImage {
  const rgb = new Float32Array(width * height * 3);
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) rgb.fill(level(x, y), (y * width + x) * 3, (y * width + x + 1) * 3);
  return { width, height, rgb };
}

/** The red levels of the piece's touched canvas pixels, row by row. */
function touched({ pixels, part }: ReturnType<typeof shrinkPiece>): number[][] {
  const rows: number[][] = [];
  for (let y = part.y; y < part.y + part.height; y++) {
    rows.push([]);
    for (let x = part.x; x < part.x + part.width; x++) rows.at(-1)!.push(pixels.data[(y * pixels.width + x) * 4]);
  }
  return rows;
}

describe('a piece of an image shown on a smaller canvas', () => {
  it('is each canvas pixel’s mean of the image pixels under it, weighted by the area they cover', () => {
    // Columns alternating 0 and 1, shrunk to a third: a canvas pixel covers 3 columns, 1.5 white, except where the pattern starts.
    const stripes = image(12, 4, (x) => x % 2);
    const shrunk = shrinkPiece(stripes, null, { width: 4, height: 1 }, PLAIN, { x: 0, y: 0, width: 12, height: 4 });
    expect(touched(shrunk)).toEqual([[Math.round(255 / 3), Math.round((2 * 255) / 3), Math.round(255 / 3), Math.round((2 * 255) / 3)]]);
    // Shrunk to 5 of 12: canvas pixel 0 covers image columns 0, 1 and 0.4 of column 2 (white 1 of 2.4).
    const fifths = shrinkPiece(stripes, null, { width: 5, height: 1 }, PLAIN, { x: 0, y: 0, width: 12, height: 4 });
    expect(touched(fifths)[0][0]).toBe(Math.round((255 * 1) / 2.4));
  });

  it('averages values as shown: clamped to 0–1 before the mean', () => {
    const highlight = image(2, 2, (x, y) => (x === 0 && y === 0 ? 8 : 0.5));
    const shrunk = shrinkPiece(highlight, null, { width: 1, height: 1 }, PLAIN, { x: 0, y: 0, width: 2, height: 2 });
    expect(touched(shrunk)).toEqual([[Math.round(((1 + 0.5 * 3) / 4) * 255)]]);
  });

  it('in path mode, averages radiance times 2^exposure, clamped after the exposure, and shows it sRGB-encoded', () => {
    // Exposure −2: the emitter's 8 shows as 1 (clamped), the walls' 0.5 as 0.125.
    const path: Quantization = { ...PLAIN_QUANTIZATION, integrator: 'path', exposure: -2 };
    const highlight = image(2, 2, (x, y) => (x === 0 && y === 0 ? 8 : 0.5));
    const shrunk = shrinkPiece(highlight, null, { width: 1, height: 1 }, path, { x: 0, y: 0, width: 2, height: 2 });
    const shown = (1 + 0.125 * 3) / 4;
    expect(touched(shrunk)).toEqual([[Math.round(255 * linearToSrgb(shown))]]);
  });

  it('touches every canvas pixel the piece overlaps and no other; neighbouring pieces share the pixel between them', () => {
    const grey = image(100, 10, () => 0.5);
    // 0.3 canvas pixels per image pixel: image columns [33, 67) cover canvas [9.9, 20.1).
    const middle = shrinkPiece(grey, null, { width: 30, height: 3 }, PLAIN, { x: 33, y: 0, width: 34, height: 10 });
    expect(middle.x + middle.part.x).toBe(9);
    expect(middle.part.width).toBe(12); // pixels 9 to 20
    expect(middle.x % 4).toBe(0); // starts at a multiple of the dither period
    expect(
      touched(middle)
        .flat()
        .every((level) => level === 128),
    ).toBe(true);
    // An end exactly on a canvas pixel's edge (10 × 0.3 = 3) does not touch the next pixel.
    const first = shrinkPiece(grey, null, { width: 30, height: 3 }, PLAIN, { x: 0, y: 0, width: 10, height: 10 });
    expect(first.part).toMatchObject({ x: 0, width: 3 });
  });

  it('counts only traced pixels: a canvas pixel half on an untraced tile shows the traced half', () => {
    const white = image(8, 4, () => 1);
    white.rgb.fill(0, 0, 4 * 3); // untraced pixels hold 0 (black)
    const rendered = new Uint8Array(8 * 4).fill(1);
    rendered.fill(0, 0, 4); // the first row's left half, pixels 0-3, not traced yet
    const shrunk = shrinkPiece(white, rendered, { width: 2, height: 1 }, PLAIN, { x: 4, y: 0, width: 4, height: 4 });
    expect(touched(shrunk)).toEqual([[255]]);
    const left = shrinkPiece(white, rendered, { width: 2, height: 1 }, PLAIN, { x: 0, y: 1, width: 4, height: 3 });
    expect(touched(left)).toEqual([[255]]);
    // Without the mask the black pixels count.
    expect(touched(shrinkPiece(white, null, { width: 2, height: 1 }, PLAIN, { x: 0, y: 0, width: 4, height: 4 }))).toEqual([[Math.round(255 * 0.75)]]);
  });

  it('dithers by canvas position, so a smooth shade comes out as the pattern the whole canvas has', () => {
    // A level between two 8-bit steps: dithering mixes both, in the same places for any piece.
    const shade = image(64, 64, () => 100.5 / 255);
    const canvas = { width: 16, height: 16 };
    const whole = touched(shrinkPiece(shade, null, canvas, DITHERED, { x: 0, y: 0, width: 64, height: 64 }));
    expect(new Set(whole.flat())).toEqual(new Set([100, 101]));
    const piece = shrinkPiece(shade, null, canvas, DITHERED, { x: 24, y: 20, width: 16, height: 16 });
    const [left, top] = [piece.x + piece.part.x, piece.y + piece.part.y];
    expect(touched(piece)).toEqual(whole.slice(top, top + piece.part.height).map((row) => row.slice(left, left + piece.part.width)));
  });
});
