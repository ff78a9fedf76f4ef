import { describe, expect, it } from 'vitest';
import { phongPower } from '../../src/tracer/phong-power.ts';

describe('phongPower: the highlight exponent', () => {
  it('agrees with Math.pow to 1e-12 for whole exponents up to the largest shininess', () => {
    for (const n of [1, 2, 3, 7, 16, 32, 48, 200, 300, 1023, 10_000]) {
      for (let i = 1; i <= 200; i++) {
        const x = i / 200;
        const expected = Math.pow(x, n);
        if (expected < 1e-300) continue;
        expect(Math.abs(phongPower(x, n) - expected) / expected).toBeLessThan(1e-12);
      }
    }
  });

  it('gives pow(0, 0) = 1 (shininess 0 lights every sample) and 0 for 0 to a positive power', () => {
    expect(phongPower(0, 0)).toBe(1);
    expect(phongPower(0.3, 0)).toBe(1);
    expect(phongPower(0, 16)).toBe(0);
  });

  it('keeps Math.pow for a fractional exponent', () => {
    expect(phongPower(0.5, 2.5)).toBe(Math.pow(0.5, 2.5));
    expect(phongPower(0.8, 0.3)).toBe(Math.pow(0.8, 0.3));
  });
});
