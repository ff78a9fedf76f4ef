import { describe, expect, it } from 'vitest';
import { PLAIN_QUANTIZATION, toRgba8 } from '../../src/tracer/quantize.ts';
import { linearToSrgb } from '../../src/tracer/srgb.ts';

describe("path mode's picture on screen (path-tracing spec §2)", () => {
  const path = { ...PLAIN_QUANTIZATION, integrator: 'path' as const };
  const byte = (light: number, exposure: number, encoding: 'none' | 'linear' | 'srgb') =>
    toRgba8(Float32Array.of(light, light, light), 1, 1, { ...path, exposure, encoding })[0];

  it('is sRGB-encoded whatever the encoding setting says', () => {
    for (const encoding of ['none', 'linear', 'srgb'] as const) expect(byte(0.2, 0, encoding)).toBe(Math.round(255 * linearToSrgb(0.2)));
  });

  it('multiplies the radiance by 2^exposure first, and clamps what is brighter than white', () => {
    expect(byte(0.1, 1, 'none')).toBe(byte(0.2, 0, 'none'));
    expect(byte(0.1, -2, 'none')).toBe(byte(0.025, 0, 'none'));
    expect(byte(3, 0, 'none')).toBe(255);
  });

  it('leaves Whitted mode as it was: exposure is not applied there', () => {
    const whitted = toRgba8(Float32Array.of(0.2, 0.2, 0.2), 1, 1, { ...PLAIN_QUANTIZATION, exposure: 3 });
    expect(whitted[0]).toBe(Math.round(0.2 * 255));
  });
});
