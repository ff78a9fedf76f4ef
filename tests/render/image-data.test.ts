import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { renderImageData } from '../../src/render/image-data.ts';
import { PLAIN_QUANTIZATION, type Quantization } from '../../src/tracer/quantize.ts';

const PLAIN: Quantization = PLAIN_QUANTIZATION;
const DITHERED: Quantization = { ...PLAIN_QUANTIZATION, dithering: true };

/**
 * Node has no ImageData: a stand-in with the browser's constructor signature records what the
 * function hands to the canvas (the browser's own one is exercised by e2e/render-window.spec.ts).
 */
class FakeImageData {
  constructor(
    readonly data: Uint8ClampedArray,
    readonly width: number,
    readonly height: number,
  ) {}
}

const globals = globalThis as { ImageData?: unknown };
beforeAll(() => {
  globals.ImageData = FakeImageData;
});
afterAll(() => {
  delete globals.ImageData;
});

/** A 4×4 image of one linear grey, halfway between two 8-bit steps (100.5 / 255). */
function flatGrey(): { width: number; height: number; rgb: Float32Array } {
  return { width: 4, height: 4, rgb: new Float32Array(4 * 4 * 3).fill(100.5 / 255) };
}

describe('renderImageData', () => {
  it('quantizes linear RGB to 8-bit RGBA without gamma, clamping out-of-range values', () => {
    const rgb = new Float32Array([0, 0.5, 1, 1.7, -0.2, 0.25]);
    const pixels = renderImageData({ width: 2, height: 1, rgb }, PLAIN);
    expect([pixels.width, pixels.height]).toEqual([2, 1]);
    expect([...pixels.data]).toEqual([0, 128, 255, 255, 255, 0, 64, 255]);
  });

  it('without dithering, a flat colour stays one flat value', () => {
    const { data } = renderImageData(flatGrey(), PLAIN);
    const reds = new Set([...data].filter((_, i) => i % 4 === 0));
    expect(reds).toEqual(new Set([101]));
  });

  it('with dithering, a colour between two steps becomes a pattern of both, averaging to it', () => {
    const { data } = renderImageData(flatGrey(), DITHERED);
    const reds = [...data].filter((_, i) => i % 4 === 0);
    expect(new Set(reds)).toEqual(new Set([100, 101]));
    // The 4×4 Bayer threshold covers the step evenly: half the pixels round each way.
    expect(reds.reduce((sum, r) => sum + r, 0) / reds.length).toBeCloseTo(100.5, 5);
    // Opaque either way: a saved PNG must not turn see-through.
    expect([...data].filter((_, i) => i % 4 === 3).every((a) => a === 255)).toBe(true);
  });
});

describe('renderImageData in bands', () => {
  /** 6 × 10 pixels of a ramp, so that every row and column differs. */
  const ramp = { width: 6, height: 10, rgb: Float32Array.from({ length: 6 * 10 * 3 }, (_, i) => (i % 97) / 96) };

  it('gives, band by band, exactly the rows of the whole image, with or without dithering, in every encoding', () => {
    for (const dithering of [false, true]) {
      for (const encoding of ['none', 'linear', 'srgb'] as const) {
        const quantization = { ...PLAIN_QUANTIZATION, dithering, encoding };
        const whole = renderImageData(ramp, quantization).data;
        const bands = [renderImageData(ramp, quantization, 0, 4), renderImageData(ramp, quantization, 4, 8), renderImageData(ramp, quantization, 8, 10)];
        expect(bands.map((band) => band.height)).toEqual([4, 4, 2]);
        expect(bands.flatMap((band) => [...band.data])).toEqual([...whole]);
      }
    }
  });

  it('refuses a band that would shift the dither pattern or leave the image', () => {
    expect(() => renderImageData(ramp, DITHERED, 2, 6)).toThrow(RangeError);
    expect(() => renderImageData(ramp, DITHERED, 8, 12)).toThrow(RangeError);
  });
});
