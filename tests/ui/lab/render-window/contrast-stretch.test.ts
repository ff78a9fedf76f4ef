import { describe, expect, it } from 'vitest';
import { levelRange, stretchContrast } from '../../../../src/ui/lab/render-window/contrast-stretch.ts';
import { PLAIN_QUANTIZATION, toRgba8 } from '../../../../src/tracer/quantize.ts';

const rgba = (...pixels: number[][]) => Uint8ClampedArray.from(pixels.flatMap(([r, g, b, a = 255]) => [r!, g!, b!, a]));

describe("stretching an image's contrast", () => {
  it('finds the darkest and brightest level over the colour channels, not alpha', () => {
    expect(levelRange(rgba([30, 40, 50, 0], [31, 56, 33, 255]))).toEqual({ low: 30, high: 56 });
    expect(levelRange(new Uint8ClampedArray(0))).toEqual({ low: 0, high: 255 });
  });

  it("maps the image's own levels onto 0..255: lowest to black, highest to white, alpha kept", () => {
    const out = stretchContrast(rgba([31, 31, 31, 200], [56, 56, 56], [43, 44, 45]));
    expect(Array.from(out.slice(0, 4))).toEqual([0, 0, 0, 200]);
    expect(Array.from(out.slice(4, 8))).toEqual([255, 255, 255, 255]);
    // (43 − 31) · 255 / 25 = 122.4
    expect(Array.from(out.slice(8, 11))).toEqual([122, 133, 143]);
  });

  it('keeps every band a band of its own and in order: a 26-level gradient becomes 26 steps about 10 levels apart', () => {
    const levels = Array.from({ length: 26 }, (_, i) => 31 + i);
    const out = stretchContrast(rgba(...levels.map((v) => [v, v, v])));
    const stretched = levels.map((_, i) => out[i * 4]!);
    expect(new Set(stretched).size).toBe(26);
    for (let i = 1; i < 26; i++) {
      expect(stretched[i]! - stretched[i - 1]!).toBeGreaterThanOrEqual(10);
      expect(stretched[i]! - stretched[i - 1]!).toBeLessThanOrEqual(11);
    }
  });

  it('a dithered gradient keeps its pattern: the two levels of each tile stay two, now far apart', () => {
    // A slow ramp over 16 × 4 pixels, quantized with the tracer's Bayer dithering.
    const width = 16;
    const rgb = new Float32Array(width * 4 * 3).map((_, i) => 0.12 + (Math.floor(i / 3) % width) * 0.0004);
    const dithered = toRgba8(rgb, width, 4, { ...PLAIN_QUANTIZATION, dithering: true });
    const range = levelRange(dithered);
    expect(range.high - range.low).toBeLessThanOrEqual(2);
    const out = stretchContrast(dithered, range);
    const before = new Set(Array.from(dithered).filter((_, i) => i % 4 === 0));
    const after = new Set(Array.from(out).filter((_, i) => i % 4 === 0));
    expect(after.size).toBe(before.size);
    expect(Math.min(...after)).toBe(0);
    expect(Math.max(...after)).toBe(255);
  });

  it('an image of one level is copied unchanged', () => {
    const flat = rgba([40, 40, 40], [40, 40, 40]);
    const out = stretchContrast(flat);
    expect(out).toEqual(flat);
    expect(out).not.toBe(flat);
  });
});
