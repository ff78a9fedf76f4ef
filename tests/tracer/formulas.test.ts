import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { angleAttenuation, distanceAttenuation } from '../../src/tracer/attenuation.ts';
import { reflect, refract, schlickReflectance } from '../../src/tracer/fresnel.ts';
import { concentricDisc } from '../../src/tracer/lights.ts';
import { PLAIN_QUANTIZATION, toRgba8 } from '../../src/tracer/quantize.ts';
import { samplePosition } from '../../src/tracer/supersampling.ts';

describe('attenuation', () => {
  it('distance attenuation is 1 / (0.04 + 0.1·d + 0.06·d²)', () => {
    expect(distanceAttenuation(0)).toBeCloseTo(25, 12);
    expect(distanceAttenuation(1)).toBeCloseTo(1 / 0.2, 12);
    expect(distanceAttenuation(4)).toBeCloseTo(1 / (0.04 + 0.4 + 0.96), 12);
  });

  it('angle attenuation is cos(α)^p inside the cone and 0 outside it', () => {
    const halfAngle = (30 * Math.PI) / 180;
    const cosHalf = Math.cos(halfAngle);
    const inside = Math.cos(halfAngle - 0.001);
    const outside = Math.cos(halfAngle + 0.001);
    expect(angleAttenuation(inside, cosHalf, 2)).toBeCloseTo(inside ** 2, 12);
    expect(angleAttenuation(outside, cosHalf, 2)).toBe(0);
    expect(angleAttenuation(inside, cosHalf, 0)).toBe(1);
    // Area lights: a 90° half-angle, nothing behind the light's plane.
    expect(angleAttenuation(-0.1, 0, 0)).toBe(0);
    expect(angleAttenuation(0.5, 0, 3)).toBeCloseTo(0.125, 12);
  });
});

describe('Fresnel and Snell', () => {
  it('Schlick gives r0 = ((η−1)/(η+1))² head-on and 1 at grazing incidence', () => {
    expect(schlickReflectance(1, 1.5)).toBeCloseTo(0.04, 12);
    expect(schlickReflectance(0, 1.5)).toBeCloseTo(1, 12);
    const cos60 = 0.5;
    expect(schlickReflectance(cos60, 1.5)).toBeCloseTo(0.04 + 0.96 * 0.5 ** 5, 12);
  });

  it('refraction obeys Snell: η₁ sinθ₁ = η₂ sinθ₂', () => {
    const theta = (40 * Math.PI) / 180;
    const d = new Vector3(Math.sin(theta), -Math.cos(theta), 0);
    const n = new Vector3(0, 1, 0);
    const out = new Vector3();
    expect(refract(d, n, 1 / 1.5, out)).toBe(true);
    expect(out.length()).toBeCloseTo(1, 12);
    expect(1.5 * out.x).toBeCloseTo(1 * Math.sin(theta), 12);
    expect(out.y).toBeLessThan(0);
  });

  it('total internal reflection beyond the critical angle', () => {
    const critical = Math.asin(1 / 1.5);
    const steep = new Vector3(Math.sin(critical + 0.01), -Math.cos(critical + 0.01), 0);
    const shallow = new Vector3(Math.sin(critical - 0.01), -Math.cos(critical - 0.01), 0);
    const n = new Vector3(0, 1, 0);
    const out = new Vector3(7, 7, 7);
    expect(refract(steep, n, 1.5, out)).toBe(false);
    expect(out.toArray()).toEqual([7, 7, 7]);
    expect(refract(shallow, n, 1.5, out)).toBe(true);
  });

  it('mirror reflection flips the normal component', () => {
    const out = reflect(new Vector3(1, -1, 0).normalize(), new Vector3(0, 1, 0), new Vector3());
    expect(out.x).toBeCloseTo(Math.SQRT1_2, 12);
    expect(out.y).toBeCloseTo(Math.SQRT1_2, 12);
  });
});

describe('supersampling positions', () => {
  it('the grid puts s×s samples at ((i+0.5)/s, (j+0.5)/s)', () => {
    const out: [number, number] = [0, 0];
    const positions = [0, 1, 2, 3].map((k) => [...samplePosition('grid', 2, k, 5, 7, 1, out)]);
    expect(positions).toEqual([
      [0.25, 0.25],
      [0.75, 0.25],
      [0.25, 0.75],
      [0.75, 0.75],
    ]);
  });

  it('jittered samples stay in their own cell; random ones anywhere in the pixel; both repeatable', () => {
    const out: [number, number] = [0, 0];
    for (let k = 0; k < 9; k++) {
      const [u, v] = samplePosition('jittered', 3, k, 2, 3, 42, out);
      expect(Math.floor(u * 3)).toBe(k % 3);
      expect(Math.floor(v * 3)).toBe(Math.floor(k / 3));
      const [ru, rv] = samplePosition('random', 3, k, 2, 3, 42, out);
      expect(ru).toBeGreaterThanOrEqual(0);
      expect(rv).toBeLessThan(1);
    }
    const first = [...samplePosition('random', 3, 4, 2, 3, 42, out)];
    expect([...samplePosition('random', 3, 4, 2, 3, 42, out)]).toEqual(first);
    expect([...samplePosition('random', 3, 4, 2, 3, 43, out)]).not.toEqual(first);
  });
});

describe('concentric disc mapping', () => {
  it('maps the square onto the unit disc, edges onto the rim', () => {
    for (const [u, v] of [
      [1, 0],
      [0, 1],
      [-1, 0.3],
      [0.5, -1],
      [1, 1],
    ]) {
      const [x, y] = concentricDisc(u, v);
      expect(Math.hypot(x, y)).toBeCloseTo(Math.max(Math.abs(u), Math.abs(v)), 12);
    }
  });
});

describe('8-bit quantization', () => {
  it('by default (no encoding, no dithering) is exactly round(clamp(c)·255)', () => {
    const values = [0, 0.5, 1, -0.2, 1.7, 0.1234, 0.99];
    const rgb = new Float32Array(values.length * 3).map((_, i) => values[Math.floor(i / 3)]);
    const rgba = toRgba8(rgb, values.length, 1, PLAIN_QUANTIZATION);
    values.forEach((c, i) => {
      const expected = Math.round(Math.min(1, Math.max(0, Math.fround(c))) * 255);
      expect([rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2], rgba[i * 4 + 3]]).toEqual([expected, expected, expected, 255]);
    });
  });

  it('with dithering keeps the mean of a flat area but breaks a band into a pattern', () => {
    const level = 10.3 / 255;
    const rgb = new Float32Array(16 * 16 * 3).fill(level);
    const plain = toRgba8(rgb, 16, 16, PLAIN_QUANTIZATION);
    const dithered = toRgba8(rgb, 16, 16, { ...PLAIN_QUANTIZATION, dithering: true });
    const red = (image: Uint8ClampedArray) => Array.from({ length: 256 }, (_, i) => image[i * 4]);
    expect(new Set(red(plain))).toEqual(new Set([10]));
    expect(new Set(red(dithered))).toEqual(new Set([10, 11]));
    const mean = red(dithered).reduce((a, b) => a + b, 0) / 256;
    expect(mean).toBeCloseTo(10.3, 1);
  });
});
