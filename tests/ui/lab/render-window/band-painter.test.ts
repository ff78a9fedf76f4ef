import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { PreviewImage, RenderImage } from '../../../../src/render/render-job.ts';
import { BandPainter } from '../../../../src/ui/lab/render-window/band-painter.ts';

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
}

function fakeContext(calls: Call[], own: boolean) {
  return {
    imageSmoothingEnabled: true,
    clearRect: () => void calls.push({ kind: 'clear', pixels: 0, args: [] }),
    putImageData: (data: FakeImageData, ...args: number[]) => void (own || calls.push({ kind: 'put', pixels: data.width * data.height, args: [data.width, data.height, ...args] })),
    drawImage: (_: unknown, ...args: number[]) => void calls.push({ kind: 'draw', pixels: args[6] * args[7], args }),
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
  vi.stubGlobal('OffscreenCanvas', class {
    constructor(readonly width: number, readonly height: number) {}
    getContext = () => fakeContext([], true);
  });
  // Each look at the clock is 3 ms later: the 8 ms budget allows a few pieces of work per frame.
  vi.spyOn(performance, 'now').mockImplementation(() => (now += 3));
});

afterEach(() => {
  vi.unstubAllGlobals();
  vi.restoreAllMocks();
});

function painterOn(width: number, height: number) {
  const canvas = { width, height, getContext: () => fakeContext(perFrame.at(-1)!, false) };
  return new BandPainter(() => canvas as unknown as HTMLCanvasElement);
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
    const painter = painterOn(4096, 4096);
    const preview: PreviewImage = { ...image(1024, 1024), block: 4 };
    painter.paintChanges(image(4096, 4096), { preview: { image: preview, rows: [0, 1024] }, tiles: [] }, true);
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
    const painter = painterOn(64, 48);
    const full = image(64, 48);
    painter.paintChanges(full, { preview: null, tiles: [{ x: 5, y: 6, width: 7, height: 3 }, { x: 0, y: 0, width: 4, height: 4 }] }, true);
    runFrames();
    const puts = perFrame.flat().filter((call) => call.kind === 'put');
    // [quantized width, height, x, y, then the part put: x, y, width, height within it]
    expect(puts.map((call) => call.args)).toEqual([[8, 5, 4, 4, 1, 2, 7, 3], [4, 4, 0, 0, 0, 0, 4, 4]]);
  });

  it('clears the canvas for a new render; the coarser preview’s rows not yet drawn are drawn from the finer one that follows', () => {
    const painter = painterOn(64, 64);
    const full = image(64, 64);
    const coarse: PreviewImage = { ...image(8, 8), block: 8 };
    const fine: PreviewImage = { ...image(16, 16), block: 4 };
    painter.paintChanges(full, { preview: { image: coarse, rows: [0, 8] }, tiles: [] }, false);
    painter.paintChanges(full, { preview: { image: fine, rows: [4, 8] }, tiles: [] }, false);
    runFrames();
    expect(perFrame.flat().map((call) => [call.kind, ...call.args])).toEqual([['clear'], ['draw', 0, 0, 16, 16, 0, 0, 64, 64]]);
    painter.paintChanges(full, { preview: null, tiles: [{ x: 0, y: 0, width: 4, height: 4 }] }, false);
    runFrames();
    expect(perFrame.at(-1)!.map((call) => call.kind)).toEqual(['put']); // the same render: no clearing
  });

  it('warms up by putting one pixel into a preview canvas of its own, which a real preview replaces at its size', () => {
    const made: { width: number; height: number; puts: number[][] }[] = [];
    vi.stubGlobal('OffscreenCanvas', class {
      readonly puts: number[][] = [];
      constructor(readonly width: number, readonly height: number) {
        made.push(this);
      }
      getContext = () => ({ putImageData: (data: FakeImageData, ...at: number[]) => void this.puts.push([data.width, data.height, ...at]) });
    });
    const painter = painterOn(64, 64);
    painter.warmUp();
    expect(made).toMatchObject([{ width: 1, height: 1, puts: [[1, 1, 0, 0]] }]);
    expect(frames).toHaveLength(0); // nothing for the visible canvas
    painter.paintChanges(image(64, 64), { preview: { image: { ...image(8, 8), block: 8 }, rows: [0, 8] }, tiles: [] }, false);
    runFrames();
    expect(made.map(({ width, height }) => [width, height])).toEqual([[1, 1], [8, 8]]);
    expect(perFrame.flat().map((call) => [call.kind, ...call.args])).toEqual([['clear'], ['draw', 0, 0, 8, 8, 0, 0, 64, 64]]);
  });
});
