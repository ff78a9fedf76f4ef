import { describe, expect, it } from 'vitest';
import type { ImageEncoding } from '../../src/scene/scene.ts';
import { sceneSchema } from '../../src/scene/scene-schema.ts';
import { PLAIN_QUANTIZATION, toRgba8 } from '../../src/tracer/quantize.ts';
import { linearToSrgb, srgbToLinear } from '../../src/tracer/srgb.ts';

/** The light a screen shows for byte b (IEC 61966-2-1's decoding, written out here). */
const shownLight = (byte: number) => {
  const v = byte / 255;
  return v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
};

/** The red bytes of a one-row image of grey values `lights`. */
function bytes(lights: number[], encoding: ImageEncoding, dithering = false): number[] {
  const rgb = Float32Array.from(lights.flatMap((light) => [light, light, light]));
  const rgba = toRgba8(rgb, lights.length, 1, { ...PLAIN_QUANTIZATION, dithering, encoding });
  return lights.map((_, i) => rgba[i * 4]!);
}

/** 100 001 light values from 0 to 1 (as float32, as the tracer hands them over). */
const ramp = Array.from({ length: 100_001 }, (_, i) => Math.fround(i / 100_000));

describe('the sRGB transfer function', () => {
  it('has the standard’s values: black, white, the joint of its two pieces, mid grey', () => {
    expect(linearToSrgb(0)).toBe(0);
    expect(linearToSrgb(1)).toBeCloseTo(1, 12);
    // The line 12.92·L meets 1.055·L^(1/2.4) − 0.055 at L = 0.0031308 (encoded 0.04045).
    expect(12.92 * 0.0031308).toBeCloseTo(1.055 * 0.0031308 ** (1 / 2.4) - 0.055, 6);
    expect(linearToSrgb(0.0031308)).toBeCloseTo(0.04045, 5);
    // 18 % grey is stored as 118 of 255; half the light as 188.
    expect(Math.round(255 * linearToSrgb(0.18))).toBe(118);
    expect(Math.round(255 * linearToSrgb(0.5))).toBe(188);
    expect(srgbToLinear(0.5)).toBeCloseTo(0.214, 3);
  });

  it('decoding undoes encoding, and every byte survives the round trip through light', () => {
    for (let i = 0; i <= 1000; i++) expect(srgbToLinear(linearToSrgb(i / 1000))).toBeCloseTo(i / 1000, 12);
    for (let byte = 0; byte < 256; byte++) {
      expect(Math.round(255 * linearToSrgb(srgbToLinear(byte / 255)))).toBe(byte);
      expect(srgbToLinear(byte / 255)).toBeCloseTo(shownLight(byte), 14);
    }
  });

  it('one step of the stored value is a larger share of the light in the dark: 28 → 29 is 5.8 % more light, 200 → 201 is 1.1 %', () => {
    expect(shownLight(29) / shownLight(28)).toBeCloseTo(1.058, 3);
    expect(shownLight(201) / shownLight(200)).toBeCloseTo(1.0113, 4);
  });
});

describe('storing the image in 8 bits', () => {
  it('by default (encoding none) writes round(255·c), unchanged: the screen then shows less light than c', () => {
    const lights = [0, 0.02, 0.1, 0.25, 0.5, 0.75, 1];
    expect(bytes(lights, 'none')).toEqual(lights.map((c) => Math.round(255 * Math.fround(c))));
    expect(sceneSchema.parse({ version: 1 }).settings.encoding).toBe('none');
    // Half the light written as 128 is shown as 22 % of white.
    expect(shownLight(bytes([0.5], 'none')[0]!)).toBeCloseTo(0.216, 3);
  });

  it('sRGB stores round(255·E(c)), dithered round(255·E(c) + threshold), as the formula gives it', () => {
    const width = 4;
    for (const dithering of [false, true]) {
      const rgb = Float32Array.from(ramp.flatMap((light) => [light, light, light]));
      const height = Math.floor(ramp.length / width);
      const rgba = toRgba8(rgb.subarray(0, width * height * 3), width, height, { ...PLAIN_QUANTIZATION, dithering, encoding: 'srgb' });
      const bayer = [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5];
      const wrong = ramp.slice(0, width * height).filter((light, i) => {
        const threshold = dithering ? (bayer[(Math.floor(i / width) % 4) * 4 + (i % width)]! + 0.5) / 16 - 0.5 : 0;
        return rgba[i * 4] !== Math.round(255 * linearToSrgb(light) + threshold);
      });
      expect(wrong).toEqual([]);
    }
  });

  it('linear and sRGB both show the light c, to within the rounding of their levels', () => {
    const largestError = (encoding: ImageEncoding) => bytes(ramp, encoding).reduce((largest, b, i) => Math.max(largest, Math.abs(shownLight(b) - ramp[i]!)), 0);
    // sRGB: half a step of the encoded value, at most 0.5/255 times decoding's steepest slope (2.28 at white).
    expect(largestError('srgb')).toBeLessThanOrEqual((0.5 / 255) * 2.28);
    // Linear: half a level of light, plus the screen's own rounding of that level's light.
    expect(largestError('linear')).toBeLessThanOrEqual(0.5 / 255 + (0.5 / 255) * 2.28);
    // Without an encoding the error is far larger: c = 0.5 is shown as 0.22.
    expect(largestError('none')).toBeGreaterThan(0.25);
  });

  it('linear light has 3 levels darker than 1 % of white and 26 darker than 10 %; sRGB has 26 and 90', () => {
    // The levels a ramp from black to white is stored in whose light is below the limit.
    const stored = { linear: bytes(ramp, 'linear'), srgb: bytes(ramp, 'srgb') };
    const levelsBelow = (limit: number, encoding: 'linear' | 'srgb') => new Set(stored[encoding].filter((b) => shownLight(b) < limit)).size;
    expect(levelsBelow(0.01, 'linear')).toBe(3);
    expect(levelsBelow(0.1, 'linear')).toBe(26);
    expect(levelsBelow(0.01, 'srgb')).toBe(26);
    expect(levelsBelow(0.1, 'srgb')).toBe(90);
    // Over the whole range both use all 256 stored levels; the screen can tell 183 of the linear ones apart.
    expect(new Set(stored.srgb).size).toBe(256);
    expect(new Set(stored.linear).size).toBe(183);
  });

  it('shows each linear level as the light it stores: level 1 as byte 13, level 3 as 28, where sRGB has a level for every byte', () => {
    expect(bytes([0, 1 / 255, 2 / 255, 3 / 255], 'linear')).toEqual([0, 13, 22, 28]);
    // The light of linear level 3 (3/255) is what sRGB stores as 28: there, one step is 5.8 % more light, not 33 %.
    expect(bytes([3 / 255], 'srgb')).toEqual([28]);
    expect(shownLight(22) / shownLight(13)).toBeCloseTo(2, 1);
  });

  it('dithers the stored level: a light between two levels becomes a pattern of both, averaging to it', () => {
    const width = 16;
    const grey = (encoding: ImageEncoding, light: number) => {
      const rgb = new Float32Array(width * 4 * 3).fill(light);
      const rgba = toRgba8(rgb, width, 4, { ...PLAIN_QUANTIZATION, dithering: true, encoding });
      return Array.from({ length: width * 4 }, (_, i) => rgba[i * 4]!);
    };
    // Linear level 2.5: half the pixels show level 2 (byte 22), half level 3 (byte 28).
    const linear = grey('linear', 2.5 / 255);
    expect(new Set(linear)).toEqual(new Set([22, 28]));
    expect(linear.filter((b) => b === 22)).toHaveLength(linear.length / 2);
    // sRGB: the encoded value 40.5 becomes 40 and 41, half each.
    const srgb = grey('srgb', srgbToLinear(40.5 / 255));
    expect(new Set(srgb)).toEqual(new Set([40, 41]));
    expect(srgb.reduce((sum, b) => sum + b, 0) / srgb.length).toBeCloseTo(40.5, 5);
  });
});
