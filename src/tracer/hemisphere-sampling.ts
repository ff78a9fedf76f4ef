import type { Vector3 } from 'three';
import type { BounceSampling } from '../scene/scene.ts';
import { perpendicularBasis } from './glossy.ts';
import { concentricDisc } from './lights.ts';

const INV_TWO_PI = 1 / (2 * Math.PI);

/**
 * A direction in the hemisphere around unit normal `n` for a diffuse bounce, from two uniform
 * numbers u, v in [0, 1), written into `out`; returns its density per steradian.
 *
 * - 'cosine': Malley's method, a uniform point of the unit disc (Shirley & Chiu's concentric
 *   map) lifted onto the hemisphere, so directions come with density cosθ/π: Lambert's
 *   cosine is sampled exactly and cancels in the estimate (pbrt-v4 §A.5.3).
 * - 'uniform': every direction of the hemisphere alike, density 1/(2π) (pbrt-v4 §A.5.2).
 * Both are unbiased; they differ in noise, which is the "better guesses" lesson.
 */
export function sampleHemisphere(kind: BounceSampling, n: Vector3, u: number, v: number, tangent: Vector3, bitangent: Vector3, out: Vector3): number {
  perpendicularBasis(n, tangent, bitangent);
  let x: number;
  let y: number;
  let z: number;
  if (kind === 'cosine') {
    [x, y] = concentricDisc(2 * u - 1, 2 * v - 1);
    z = Math.sqrt(Math.max(0, 1 - x * x - y * y));
  } else {
    z = u;
    const r = Math.sqrt(Math.max(0, 1 - z * z));
    const phi = 2 * Math.PI * v;
    x = r * Math.cos(phi);
    y = r * Math.sin(phi);
  }
  out.copy(n).multiplyScalar(z).addScaledVector(tangent, x).addScaledVector(bitangent, y).normalize();
  return hemisphereDensity(kind, z);
}

/** The density per steradian of a direction at cosθ from the normal, for `kind`. */
export function hemisphereDensity(kind: BounceSampling, cosTheta: number): number {
  if (cosTheta <= 0) return 0;
  return kind === 'cosine' ? cosTheta / Math.PI : INV_TWO_PI;
}
