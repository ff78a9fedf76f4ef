import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { PreviewImage, RenderImage } from '../../../../src/render/render-job.ts';
import { BandPainter } from '../../../../src/ui/lab/render-window/band-painter.ts';
import type { CanvasView } from '../../../../src/ui/lab/render-window/image-zoom.ts';
import { PLAIN_QUANTIZATION, type Quantization } from '../../../../src/tracer/quantize.ts';

const PLAIN: Quantization = PLAIN_QUANTIZATION;
const DITHERED: Quantization = { ...PLAIN_QUANTIZATION, dithering: true };

/**
 * Node has no canvas: stand-ins record what the painter does in each animation frame (how
 * many pixels it quantizes, what it puts and draws where). The browser's own canvas is
 * exercised by e2e/render-progress.spec.ts.
 */
class FakeImageData {
  readonly data: Uint8ClampedArray;
  readonly width: number;
  readonly height: number;
  /** As ImageData: (data, width, height) or a blank (width, height). */
  constructor(data: Uint8ClampedArray | number, width: number, height?: number) {
    if (typeof data === 'number') [this.data, this.width, this.height] = [new Uint8ClampedArray(data * width * 4), data, width];
    else [this.data, this.width, this.height] = [data, width, height!];
  }
}

interface Call {
  kind: 'put' | 'draw' | 'clear';
  /** Pixels quantized for a put; the destination rectangle's for a draw. */
  pixels: number;
  args: number[];
  /** A put's pixels. */
  data?: Uint8ClampedArray;
}

function fakeContext(calls: Call[], own: boolean, canvas?: { width: number; height: number }) {
  return {
    canvas,
    imageSmoothingEnabled: true,
    imageSmoothingQuality: 'low',
    clearRect: () => void calls.push({ kind: 'clear', pixels: 0, args: [] }),
    putImageData: (data: FakeImageData, ...args: number[]) =>
      void (own || calls.push({ kind: 'put', pixels: data.width * data.height, args: [data.width, data.height, ...args], data: data.data })),
    // drawImage(source, dx, dy, dw, dh) or (source, sx, sy, sw, sh, dx, dy, dw, dh): recorded as the latter.
    drawImage: (source: { width: number; height: number }, ...args: number[]) => {
      if (own) return;
      // (+ 0: a draw at -0 is a draw at 0)
      const all = (args.length === 4 ? [0, 0, source.width, source.height, ...args] : args).map((value) => value + 0);
      calls.push({ kind: 'draw', pixels: all[6] * all[7], args: all });
    },
  };
}

const frames: FrameRequestCallback[] = [];
/** Per frame, what the painter did. */
let perFrame: Call[][] = [];
let now = 0;

beforeEach(() => {
  frames.length = 0;
  perFrame = [];
  vi.stubGlobal('ImageData', FakeImageData);
  vi.stubGlobal('requestAnimationFrame', (callback: FrameRequestCallback) => frames.push(callback));
  vi.stubGlobal('cancelAnimationFrame', () => (frames.length = 0));
  vi.stubGlobal(
    'OffscreenCanvas',
    class {
      constructor(
        readonly width: number,
        readonly height: number,
      ) {}
      getContext = () => fakeContext([], true);
    },
  );
  // Each look at the clock is 3 ms later: the 8 ms budget allows a few pieces of work per frame.
  vi.spyOn(performance, 'now').mockImplementation(() => (now += 3));
});

afterEach(() => {
  vi.unstubAllGlobals();
  vi.restoreAllMocks();
});

/** All of an image shown at `full` canvas pixels. */
const whole = (full: { width: number; height: number }): CanvasView => ({ full, window: { x: 0, y: 0, ...full } });

/** A painter on a canvas now `width` × `height`, showing `view` (default: all of the image at its own size). */
function painterOn(width: number, height: number, view?: CanvasView) {
  const canvas: { width: number; height: number; getContext: () => unknown } = {
    width,
    height,
    getContext: () => fakeContext(perFrame.at(-1)!, false, canvas),
  };
  const painter = new BandPainter(
    () => canvas as unknown as HTMLCanvasElement,
    // A new object each time, as the viewer's tracedView is.
    (image) => {
      const { full, window } = view ?? whole(image);
      return { full: { ...full }, window: { ...window } };
    },
  );
  return { painter, canvas };
}

/** Runs animation frames until the painter asks for no more. */
function runFrames(): void {
  while (frames.length > 0) {
    perFrame.push([]);
    frames.shift()!(0);
  }
}

const image = (width: number, height: number): RenderImage => ({ width, height, rgb: new Float32Array(width * height * 3) });

describe('the render window painter', () => {
  it('quantizes a 4096² render’s 4×4 preview at its own resolution and draws it scaled up, a few bands a frame', () => {
    const { painter } = painterOn(4096, 4096);
    const preview: PreviewImage = { ...image(1024, 1024), block: 4 };
    painter.paintChanges(image(4096, 4096), { preview: { image: preview, rows: [0, 1024] }, tiles: [] }, DITHERED);
    runFrames();
    const draws = perFrame.flat().filter((call) => call.kind === 'draw');
    // Every preview pixel once (its own canvas), every canvas pixel covered once by the scaled draws.
    expect(draws.reduce((sum, call) => sum + call.pixels, 0)).toBe(4096 * 4096);
    expect(draws.map((call) => call.args.slice(0, 4))).toEqual(draws.map((_, i) => [0, i * 64, 1024, 64]));
    expect(perFrame.flat().some((call) => call.kind === 'put')).toBe(false);
    // The 8 ms budget: at most two bands of 64 k pixels before the clock says stop.
    expect(Math.max(...perFrame.map((calls) => calls.filter((call) => call.kind === 'draw').length))).toBeLessThanOrEqual(2);
  });

  it('puts each tile of the image exactly as its rectangle, quantized from the dither pattern’s corner before it', () => {
    const { painter } = painterOn(64, 48);
    const full = image(64, 48);
    painter.paintChanges(
      full,
      {
        preview: null,
        tiles: [
          { x: 5, y: 6, width: 7, height: 3 },
          { x: 0, y: 0, width: 4, height: 4 },
        ],
      },
      DITHERED,
    );
    runFrames();
    const puts = perFrame.flat().filter((call) => call.kind === 'put');
    // [quantized width, height, x, y, then the part put: x, y, width, height within it]
    expect(puts.map((call) => call.args)).toEqual([
      [8, 5, 4, 4, 1, 2, 7, 3],
      [4, 4, 0, 0, 0, 0, 4, 4],
    ]);
  });

  it('clears the canvas for a new render; the coarser preview’s rows not yet drawn are drawn from the finer one that follows', () => {
    const { painter } = painterOn(64, 64);
    const full = image(64, 64);
    const coarse: PreviewImage = { ...image(8, 8), block: 8 };
    const fine: PreviewImage = { ...image(16, 16), block: 4 };
    painter.paintChanges(full, { preview: { image: coarse, rows: [0, 8] }, tiles: [] }, PLAIN);
    painter.paintChanges(full, { preview: { image: fine, rows: [4, 8] }, tiles: [] }, PLAIN);
    runFrames();
    expect(perFrame.flat().map((call) => [call.kind, ...call.args])).toEqual([['clear'], ['draw', 0, 0, 16, 16, 0, 0, 64, 64]]);
    painter.paintChanges(full, { preview: null, tiles: [{ x: 0, y: 0, width: 4, height: 4 }] }, PLAIN);
    runFrames();
    expect(perFrame.at(-1)!.map((call) => call.kind)).toEqual(['put']); // the same render: no clearing
  });

  it('warms up by putting one pixel into a preview canvas of its own, which a real preview replaces at its size', () => {
    const made: { width: number; height: number; puts: number[][] }[] = [];
    vi.stubGlobal(
      'OffscreenCanvas',
      class {
        readonly puts: number[][] = [];
        constructor(
          readonly width: number,
          readonly height: number,
        ) {
          made.push(this);
        }
        getContext = () => ({ putImageData: (data: FakeImageData, ...at: number[]) => void this.puts.push([data.width, data.height, ...at]) });
      },
    );
    const { painter } = painterOn(64, 64);
    painter.warmUp();
    expect(made).toMatchObject([{ width: 1, height: 1, puts: [[1, 1, 0, 0]] }]);
    expect(frames).toHaveLength(0); // nothing for the visible canvas
    painter.paintChanges(image(64, 64), { preview: { image: { ...image(8, 8), block: 8 }, rows: [0, 8] }, tiles: [] }, PLAIN);
    runFrames();
    expect(made.map(({ width, height }) => [width, height])).toEqual([
      [1, 1],
      [8, 8],
    ]);
    expect(perFrame.flat().map((call) => [call.kind, ...call.args])).toEqual([['clear'], ['draw', 0, 0, 8, 8, 0, 0, 64, 64]]);
  });

  it('puts the canvas pixels each tile of an image shown smaller touches, averaging only the traced image pixels', () => {
    const { painter, canvas } = painterOn(100, 100, whole({ width: 30, height: 30 }));
    // Traced so far: columns [0, 33), white; the rest holds 0 (black) until its tile comes.
    const full = image(100, 100);
    for (let y = 0; y < 100; y++) full.rgb.fill(1, y * 300, y * 300 + 33 * 3);
    painter.paintChanges(full, { preview: null, tiles: [{ x: 0, y: 0, width: 33, height: 100 }] }, PLAIN);
    runFrames();
    expect([canvas.width, canvas.height]).toEqual([30, 30]);
    const [first] = perFrame.flat().filter((call) => call.kind === 'put');
    // [pixels' width, height, x, y, then the part put: x, y, width, height]: canvas columns
    // [0, 10), the last of them shared with the next tile (33 × 0.3 = 9.9)
    expect(first.args).toEqual([10, 30, 0, 0, 0, 0, 10, 30]);
    expect(first.data![9 * 4]).toBe(255); // the shared pixel: white, not mixed with the black not traced yet
    painter.paintChanges(full, { preview: null, tiles: [{ x: 33, y: 0, width: 67, height: 100 }] }, PLAIN);
    runFrames();
    const second = perFrame.flat().filter((call) => call.kind === 'put')[1];
    // From column 8 (a multiple of the dither period); the part put starts at the shared pixel 9.
    expect(second.args).toEqual([22, 30, 8, 0, 1, 0, 21, 30]);
    // Pixel 9 now: 0.9 of it white, 0.1 black (traced now): 229.5, rounded either way.
    expect(Math.abs(second.data![1 * 4] - 0.9 * 255)).toBeLessThanOrEqual(0.5);
  });

  it('paints a finished image again at a new scale, over the old picture scaled', () => {
    const shown = whole({ width: 4096, height: 64 });
    const { painter, canvas } = painterOn(4096, 64, shown);
    painter.paint(image(4096, 64), PLAIN);
    runFrames();
    expect(new Set(perFrame.flat().map((call) => call.kind))).toEqual(new Set(['clear', 'put'])); // at its own size: put exactly
    Object.assign(shown, whole({ width: 1024, height: 16 }));
    perFrame = [];
    painter.reframe();
    runFrames();
    expect([canvas.width, canvas.height]).toEqual([1024, 16]);
    const [ground, ...bands] = perFrame.flat();
    expect(ground.args).toEqual([0, 0, 4096, 64, 0, 0, 1024, 16]);
    // Bands of 16 image rows (65 536 pixels), 4 canvas rows each, top to bottom.
    expect(bands.map((call) => [call.kind, ...call.args])).toEqual([0, 4, 8, 12].map((top) => ['put', 1024, 4, 0, top, 0, 0, 1024, 4]));
  });

  it('paints a running render again at a new scale: the preview over the old picture, then the tiles', () => {
    const shown = whole({ width: 64, height: 64 });
    const { painter } = painterOn(64, 64, shown);
    const full = image(64, 64);
    painter.paintChanges(full, { preview: { image: { ...image(8, 8), block: 8 }, rows: [0, 8] }, tiles: [{ x: 0, y: 0, width: 16, height: 16 }] }, PLAIN);
    runFrames();
    expect(perFrame.flat().map((call) => call.kind)).toEqual(['clear', 'draw', 'put']);
    painter.paintChanges(full, { preview: null, tiles: [{ x: 0, y: 0, width: 16, height: 16 }] }, PLAIN); // the next pass's same tile
    runFrames();
    Object.assign(shown, whole({ width: 32, height: 32 }));
    perFrame = [];
    painter.reframe();
    runFrames();
    expect(perFrame.flat().map((call) => [call.kind, ...call.args])).toEqual([
      ['draw', 0, 0, 64, 64, 0, 0, 32, 32], // the old canvas
      ['draw', 0, 0, 8, 8, 0, 0, 32, 32], // the preview
      ['put', 8, 8, 0, 0, 0, 0, 8, 8], // the tile, once
    ]);
  });

  it('asks for no frame when the view changes with no image to paint', () => {
    const { painter } = painterOn(64, 64, whole({ width: 32, height: 32 }));
    painter.reframe();
    expect(frames).toHaveLength(0);
  });

  it('paints only the window on screen, at its place in the canvas', () => {
    // A 64 × 64 image at its own scale, of which columns 16–47 and rows 8–23 are on screen.
    const view: CanvasView = { full: { width: 64, height: 64 }, window: { x: 16, y: 8, width: 32, height: 16 } };
    const { painter, canvas } = painterOn(64, 64, view);
    painter.paintChanges(
      image(64, 64),
      {
        preview: null,
        tiles: [
          { x: 0, y: 0, width: 32, height: 32 },
          { x: 0, y: 32, width: 32, height: 32 },
        ],
      },
      PLAIN,
    );
    runFrames();
    expect([canvas.width, canvas.height]).toEqual([32, 16]);
    // The first tile's part on screen, columns 16–31 and rows 8–23, at the canvas's (0, 0); the second tile is off screen.
    expect(perFrame.flat().map((call) => [call.kind, ...call.args])).toEqual([['put', 16, 16, 0, 0, 0, 0, 16, 16]]);
  });

  it('a scroll moves the old pixels to their new place and paints the window again', () => {
    const view: CanvasView = { full: { width: 64, height: 64 }, window: { x: 16, y: 8, width: 32, height: 16 } };
    const { painter } = painterOn(64, 64, view);
    painter.paint(image(64, 64), PLAIN);
    runFrames();
    view.window = { x: 24, y: 8, width: 32, height: 16 };
    perFrame = [];
    painter.reframe();
    runFrames();
    const [ground, ...bands] = perFrame.flat();
    expect(ground.args).toEqual([0, 0, 32, 16, -8, 0, 32, 16]); // 8 pixels to the left
    // Rows 8–23 of columns 24–55 again (quantized from the dither period's corner, row 8 and column 24).
    expect(bands.map((call) => [call.kind, ...call.args])).toEqual([['put', 32, 16, 0, 0, 0, 0, 32, 16]]);
  });

  it('stretches the contrast of what it paints, and paints it all again when the stretch changes', () => {
    const { painter } = painterOn(16, 16);
    const grey = image(16, 16);
    grey.rgb.fill(15 / 255);
    painter.paint(grey, PLAIN);
    runFrames();
    expect(
      perFrame
        .flat()
        .filter((call) => call.kind === 'put')
        .map((call) => call.data![0]),
    ).toEqual([15]);
    perFrame = [];
    painter.setStretch({ low: 10, high: 20 });
    runFrames();
    // 15 on a stretch of 10–20: round(255 · 5 / 10) = 128.
    expect(perFrame.flat().map((call) => [call.kind, call.data?.[0]])).toEqual([['put', 128]]);
    perFrame = [];
    painter.setStretch({ low: 10, high: 20 }); // the same stretch: nothing to do
    expect(frames).toHaveLength(0);
  });
});
