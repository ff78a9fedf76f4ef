import { describe, expect, it } from 'vitest';
import { fresnelDielectric } from '../../src/tracer/dielectric-fresnel.ts';
import { schlickReflectance } from '../../src/tracer/fresnel.ts';

describe('the exact Fresnel reflectance of a dielectric', () => {
  it('is ((η − 1)/(η + 1))² at normal incidence, from either side', () => {
    expect(fresnelDielectric(1, 1.5)).toBeCloseTo(0.04, 12);
    expect(fresnelDielectric(1, 1 / 1.5)).toBeCloseTo(0.04, 12);
  });

  it('is 1 past the critical angle inside glass, and just below it is less', () => {
    const critical = Math.asin(1 / 1.5);
    expect(fresnelDielectric(Math.cos(critical + 0.01), 1 / 1.5)).toBe(1);
    expect(fresnelDielectric(Math.cos(critical - 0.01), 1 / 1.5)).toBeLessThan(1);
  });

  it("is 0 for p-polarized light at Brewster's angle, so unpolarized light reflects half of the s share", () => {
    // At tan θB = η the parallel reflectance vanishes; what is left is Rs/2 (Hecht §4.6.3).
    const brewster = Math.atan(1.5);
    const cosI = Math.cos(brewster);
    const cosT = Math.sqrt(1 - Math.sin(brewster) ** 2 / 1.5 ** 2);
    const rs = ((cosI - 1.5 * cosT) / (cosI + 1.5 * cosT)) ** 2;
    expect(fresnelDielectric(cosI, 1.5)).toBeCloseTo(rs / 2, 12);
  });

  it('reaches 1 at grazing incidence and stays within 0.05 of Schlick entering glass', () => {
    expect(fresnelDielectric(0, 1.5)).toBeCloseTo(1, 12);
    for (let cos = 0.05; cos <= 1; cos += 0.05) expect(Math.abs(fresnelDielectric(cos, 1.5) - schlickReflectance(cos, 1.5))).toBeLessThan(0.05);
  });
});
