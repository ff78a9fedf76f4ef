import { describe, expect, it } from 'vitest';
import { LOBE_SIZE, lobeDensity, lobeRadius } from '../../src/view/sampling-lobe.ts';

/** ∫ over the hemisphere of density(θ) dω, by the midpoint rule in θ (dω = 2π sinθ dθ). */
function total(sampling: 'cosine' | 'uniform'): number {
  const steps = 2000;
  let sum = 0;
  for (let i = 0; i < steps; i++) {
    const theta = ((i + 0.5) / steps) * (Math.PI / 2);
    sum += lobeDensity(sampling, Math.cos(theta)) * 2 * Math.PI * Math.sin(theta) * (Math.PI / 2 / steps);
  }
  return sum;
}

describe('the sampling lobe drawn at a diffuse bounce', () => {
  it('draws densities that are probability densities over the hemisphere', () => {
    expect(total('cosine')).toBeCloseTo(1, 5);
    expect(total('uniform')).toBeCloseTo(1, 5);
    expect(lobeDensity('cosine', -0.2)).toBe(0);
    expect(lobeDensity('uniform', -0.2)).toBe(0);
  });

  it('reaches LOBE_SIZE along the normal for cosine, half that everywhere for uniform', () => {
    const cosine = { sampling: 'cosine' as const, size: LOBE_SIZE };
    const uniform = { sampling: 'uniform' as const, size: LOBE_SIZE };
    expect(lobeRadius(cosine, 1)).toBeCloseTo(LOBE_SIZE, 12);
    expect(lobeRadius(cosine, 0)).toBe(0);
    expect(lobeRadius(cosine, 0.5)).toBeCloseTo(LOBE_SIZE / 2, 12);
    for (const cos of [1, 0.5, 0]) expect(lobeRadius(uniform, cos)).toBeCloseTo(LOBE_SIZE / 2, 12);
  });
});
